// The planar four-bar linkage, shared by the example and the tests: ground
// pivots O and D = d n1; crank OP (length a) at q1 from n1 (frame A), coupler
// PQ (b) at q2 (B), rocker DQ (c) at q3 (C), all angles absolute about n3.
// The loop closes when Q reached through the crank and the coupler is Q
// reached through the rocker: two holonomic constraints make q2, q3
// dependent, and their time derivatives make u2, u3 dependent on u1 = q1'.
#pragma once

#include <kane/kane.hpp>

namespace models::fourbar {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct a_ : kane::parameter<1> {};  // crank
struct b_ : kane::parameter<2> {};  // coupler
struct c_ : kane::parameter<3> {};  // rocker
struct d_ : kane::parameter<4> {};  // ground
inline constexpr a_ a;
inline constexpr b_ b;
inline constexpr c_ c;
inline constexpr d_ d;

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B : kane::frame<N, kane::simple<kane::axis::z, q<2>>> {};
struct C : kane::frame<N, kane::simple<kane::axis::z, q<3>>> {};

struct O : kane::origin<N> {};
struct P : kane::point<O, a * e<A, 1>> {};  // crank tip
struct Q : kane::point<P, b * e<B, 1>> {};  // coupler tip, on the rocker when the loop closes

// r^OQ - d n1 - c c1 = 0, in n1 and n2.
inline constexpr auto gap = kane::position<O, Q>() - d * e<N, 1> - c * e<C, 1>;
using loop = kane::holonomic<kane::dependent_coordinates<2, 3>, dot(gap, e<N, 1>), dot(gap, e<N, 2>)>;
using speeds = kane::qdot_speeds<3>;
using rates = loop::velocity_constraints<speeds>;  // u2, u3 = A u1
using state = kane::state<double, 3, 3, 4>;
using evaluator = kane::evaluator<state, kane::frames<A, B, C>, kane::level::velocity, speeds>;
}  // namespace models::fourbar
