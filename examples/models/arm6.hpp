// The 6-revolute arm, shared by the example, the tests and the benchmarks:
// joint axes z, y, y, x, y, x, each about the previous body's axis; joint i+1
// at L_i along b_i x; the end point at L6 along b6 x (L = 0.3, 0.25, 0.2,
// 0.15, 0.1, 0.05).
#pragma once

#include <kane/kane.hpp>

namespace models::arm6 {
template <std::size_t I>
using q = kane::coordinate<I>;
using kane::axis::x;
using kane::axis::y;
using kane::axis::z;

struct N : kane::root_frame {};
struct B1 : kane::frame<N, kane::simple<z, q<1>>> {};
struct B2 : kane::frame<B1, kane::simple<y, q<2>>> {};
struct B3 : kane::frame<B2, kane::simple<y, q<3>>> {};
struct B4 : kane::frame<B3, kane::simple<x, q<4>>> {};
struct B5 : kane::frame<B4, kane::simple<y, q<5>>> {};
struct B6 : kane::frame<B5, kane::simple<x, q<6>>> {};

struct O : kane::origin<N> {};
struct J2 : kane::point<O, 0.3 * kane::e<B1, 1>> {};
struct J3 : kane::point<J2, 0.25 * kane::e<B2, 1>> {};
struct J4 : kane::point<J3, 0.2 * kane::e<B3, 1>> {};
struct J5 : kane::point<J4, 0.15 * kane::e<B4, 1>> {};
struct J6 : kane::point<J5, 0.1 * kane::e<B5, 1>> {};
struct End : kane::point<J6, 0.05 * kane::e<B6, 1>> {};
}  // namespace models::arm6
