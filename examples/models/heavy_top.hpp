// A heavy symmetric top on a fixed point O, shared by the tests and the benchmarks: A = N
// turned about n3 by q1, B = A about a1 by q2, C = B about b3 by q3 (3-1-3 angles); the speeds
// are the body rates u_i = ^N w^C . c_i. Mass 1.5 at Co = O + 0.3 c3, inertia about Co in C
// diag(0.02, 0.02, 0.035), gravity -9.81 n3: every parameter a literal.
#pragma once

#include <kane/kane.hpp>

namespace models::heavy_top {
using kane::dot;
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, q<2>>> {};
struct C : kane::frame<B, kane::simple<kane::axis::z, q<3>>> {};
struct O : kane::origin<N> {};
struct Co : kane::point<O, literal(0.3) * e<C, 3>> {};
inline constexpr auto w = kane::angular_velocity<N, C>();
using speeds = kane::speeds<dot(w, e<C, 1>), dot(w, e<C, 2>), dot(w, e<C, 3>)>;
using system = kane::system<
    kane::rigid_body<C, Co, literal(1.5), kane::inertia<C, Co, literal(0.02), literal(0.02), literal(0.035)>>,
    kane::gravity<literal(-9.81) * e<N, 3>>>;
using state = kane::state<double, 3, 3>;
using evaluator = kane::evaluator<state, kane::frames<C>, kane::level::acceleration, speeds>;
}  // namespace models::heavy_top
