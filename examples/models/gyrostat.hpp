// A spacecraft with a reaction wheel (a gyrostat), shared by the tests and the benchmarks: B
// free, Euler parameters q1..q4 (scalar first) of B in N, mass centre Bo = O + q5 n1 + q6 n2
// + q7 n3; speeds u1..u3 = ^N w^B . b_i, u4..u6 = q5', q6', q7'; the wheel W spins about b3 at
// the free speed u7 = ^B w^W . b3, its centre at Bo. B: mass 10, inertia about Bo in B
// diag(1.2, 1.5, 1.9); W: mass 0.5, inertia diag(0.01, 0.01, 0.02), given in B (W turns about
// its symmetry axis). No load; every parameter a literal.
#pragma once

#include <kane/kane.hpp>

namespace models::gyrostat {
using kane::dot;
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
struct W : kane::frame<B, kane::spin<kane::axis::z, kane::speed<7>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::q<5> * e<N, 1> + kane::q<6> * e<N, 2> + kane::q<7> * e<N, 3>> {};
inline constexpr auto w = kane::angular_velocity<N, B>();
using speeds = kane::speeds<dot(w, e<B, 1>), dot(w, e<B, 2>), dot(w, e<B, 3>), kane::dt(kane::q<5>),
                            kane::dt(kane::q<6>), kane::dt(kane::q<7>), kane::free_speed, kane::unit_norm<B>>;
using system = kane::system<
    kane::rigid_body<B, Bo, literal(10), kane::inertia<B, Bo, literal(1.2), literal(1.5), literal(1.9)>>,
    kane::rigid_body<W, Bo, literal(0.5), kane::inertia<B, Bo, literal(0.01), literal(0.01), literal(0.02)>>>;
using state = kane::state<double, 7, 7>;
using evaluator = kane::evaluator<state, kane::frames<W>, kane::level::acceleration, speeds>;
}  // namespace models::gyrostat
