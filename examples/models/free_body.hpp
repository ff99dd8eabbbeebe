// A free rigid body B, shared by the example, the tests and the benchmark:
// attitude by Euler parameters q1..q4 (scalar first, SymPy's 'Quaternion'),
// mass centre Bo at q5 n1 + q6 n2 + q7 n3, a point P fixed in B at a b1 + b b2 + c b3.
// Speeds: the body rates u1..u3 = ^N w^B . b_i and u4..u6 = q5', q6', q7';
// the held row unit_norm<B> (q . q' = 0) makes 7 kinematic equations of 6 speeds.
#pragma once

#include <kane/kane.hpp>

namespace models::free_body {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct a_ : kane::parameter<1> {};
struct b_ : kane::parameter<2> {};
struct c_ : kane::parameter<3> {};
inline constexpr a_ a;
inline constexpr b_ b;
inline constexpr c_ c;

struct N : kane::root_frame {};
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::q<5> * e<N, 1> + kane::q<6> * e<N, 2> + kane::q<7> * e<N, 3>> {};
struct P : kane::point<Bo, a * e<B, 1> + b * e<B, 2> + c * e<B, 3>> {};

inline constexpr auto w = kane::angular_velocity<N, B>();
using speeds = kane::speeds<dot(w, e<B, 1>), dot(w, e<B, 2>), dot(w, e<B, 3>), kane::dt(kane::q<5>),
                            kane::dt(kane::q<6>), kane::dt(kane::q<7>), kane::unit_norm<B>>;
using state = kane::state<double, 7, 6, 3>;
using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::acceleration, speeds>;
}  // namespace models::free_body
