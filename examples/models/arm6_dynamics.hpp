// The 6-revolute arm of arm6.hpp with a mass at every link, shared by the example,
// the tests and the benchmarks: link i has mass m_i at its middle (L_i / 2 along
// b_i x) and a full inertia about that point in B_i; gravity -9.81 n3. `driven`
// adds joint torques as inputs: r_i k_i on B_i and -r_i k_i on its parent.
#pragma once

#include "arm6.hpp"
#include "arm6_parameters.hpp"

namespace models::arm6 {

template <class B, class From, std::size_t I>
struct centre : kane::point<From, kane::literal(length[I] / 2) * kane::e<B, 1>> {};
struct C1 : centre<B1, O, 0> {};
struct C2 : centre<B2, J2, 1> {};
struct C3 : centre<B3, J3, 2> {};
struct C4 : centre<B4, J4, 3> {};
struct C5 : centre<B5, J5, 4> {};
struct C6 : centre<B6, J6, 5> {};
template <class B, class C, std::size_t I>
using link = kane::rigid_body<B, C, kane::literal(mass[I]),
                              kane::inertia<B, C, kane::literal(inertia[I][0]), kane::literal(inertia[I][1]),
                                            kane::literal(inertia[I][2]), kane::literal(inertia[I][3]),
                                            kane::literal(inertia[I][4]), kane::literal(inertia[I][5])>>;
using links =
    kane::system<link<B1, C1, 0>, link<B2, C2, 1>, link<B3, C3, 2>, link<B4, C4, 3>, link<B5, C5, 4>,
                 link<B6, C6, 5>, kane::gravity<kane::literal(-g) * kane::e<N, 3>>>;
// r_i k_i on B (k_i = e_Bk) and -r_i k_i on P
template <class P, class B, std::size_t I, int K>
using motor =
    kane::system<kane::torque<B, kane::r<I> * kane::e<B, K>>, kane::torque<P, -kane::r<I> * kane::e<B, K>>>;
using driven = kane::system<links, motor<N, B1, 1, 3>, motor<B1, B2, 2, 2>, motor<B2, B3, 3, 2>,
                            motor<B3, B4, 4, 1>, motor<B4, B5, 5, 2>, motor<B5, B6, 6, 1>>;
}  // namespace models::arm6
