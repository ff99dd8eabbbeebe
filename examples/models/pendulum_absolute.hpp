// A planar double pendulum of point masses on absolute angles, as a textbook and SymPy write it,
// shared by the tests and the benchmarks: A = N turned about n3 by q1, B = N about n3 by q2;
// P1 = O + 1.2 a1 (mass 1.0), P2 = P1 + 0.8 b1 (mass 0.7); gravity 9.81 n1; u = q'.
#pragma once

#include <kane/kane.hpp>

namespace models::pendulum_absolute {
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B : kane::frame<N, kane::simple<kane::axis::z, q<2>>> {};
struct O : kane::origin<N> {};
struct P1 : kane::point<O, literal(1.2) * e<A, 1>> {};
struct P2 : kane::point<P1, literal(0.8) * e<B, 1>> {};
using system = kane::system<kane::particle<P1, literal(1.0)>, kane::particle<P2, literal(0.7)>,
                            kane::gravity<literal(9.81) * e<N, 1>>>;
}  // namespace models::pendulum_absolute
