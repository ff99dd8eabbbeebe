// A 3D double pendulum, shared by the example and the tests (SymPy's twin:
// tests/data/gen_dynamics.py): link A turns about n1 by q1, link B about a2 by q2;
// rigid links with full inertia about their mass centres, a particle at the tip Q,
// gravity -g n3, a torsion spring k and damper c at the joint, air drag d at the tip.
// Parameters p1..p21: lA, lB, mA, mB, mQ, IA1, IA2, IA3, IA12, IA23, IA31, IB1, IB2, IB3,
// IB12, IB23, IB31, g, k, c, d. Speeds u = q'.
#pragma once

#include <kane/kane.hpp>

namespace models::pendulum3d {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::x, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::y, q<2>>> {};
struct O : kane::origin<N> {};
struct Ao : kane::point<O, -p<1> * kane::constant<1, 2>{} * e<A, 3>> {};
struct J : kane::point<O, -p<1> * e<A, 3>> {};  // the joint
struct Bo : kane::point<J, -p<2> * kane::constant<1, 2>{} * e<B, 3>> {};
struct Q : kane::point<J, -p<2> * e<B, 3>> {};  // the tip

inline constexpr auto joint = (p<19> * kane::q<2> + p<20> * kane::u<2>)*e<A, 2>;
using system = kane::system<
    kane::rigid_body<A, Ao, p<3>, kane::inertia<A, Ao, p<6>, p<7>, p<8>, p<9>, p<10>, p<11>>>,
    kane::rigid_body<B, Bo, p<4>, kane::inertia<B, Bo, p<12>, p<13>, p<14>, p<15>, p<16>, p<17>>>,
    kane::particle<Q, p<5>>, kane::gravity<-p<18> * e<N, 3>>, kane::torque<B, -joint>, kane::torque<A, joint>,
    kane::force<Q, -p<21> * kane::velocity<N, Q>()>>;
// V = g (mA z_Ao + mB z_Bo + mQ z_Q) + k q2^2 / 2
inline constexpr auto potential =
    p<18> * (p<3> * dot(kane::position<O, Ao>(), e<N, 3>) + p<4> * dot(kane::position<O, Bo>(), e<N, 3>) +
             p<5> * dot(kane::position<O, Q>(), e<N, 3>)) +
    kane::constant<1, 2>{} * p<19> * kane::q<2> * kane::q<2>;
using state = kane::state<double, 2, 2, 21>;
using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::acceleration, kane::qdot_speeds<2>>;
}  // namespace models::pendulum3d
