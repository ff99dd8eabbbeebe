// A 3D double pendulum, shared by the example and the tests (SymPy's twin:
// tests/data/gen_dynamics.py): link A turns about n1 by q1, link B about a2 by q2;
// rigid links with full inertia about their mass centres, a particle at the tip Q,
// gravity -g n3, a torsion spring k and damper c at the joint, air drag d at the tip.
// Parameters by name, p1..p21 in this order (s[lA] = 1.5, or s.p by position). Speeds u = q'.
#pragma once

#include <kane/kane.hpp>

namespace models::pendulum3d {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};
inline constexpr kane::parameter<1> lA{};  // link lengths
inline constexpr kane::parameter<2> lB{};
inline constexpr kane::parameter<3> mA{};  // masses
inline constexpr kane::parameter<4> mB{};
inline constexpr kane::parameter<5> mQ{};
inline constexpr kane::parameter<6> IA1{};  // A's inertia about Ao in A
inline constexpr kane::parameter<7> IA2{};
inline constexpr kane::parameter<8> IA3{};
inline constexpr kane::parameter<9> IA12{};
inline constexpr kane::parameter<10> IA23{};
inline constexpr kane::parameter<11> IA31{};
inline constexpr kane::parameter<12> IB1{};  // B's about Bo in B
inline constexpr kane::parameter<13> IB2{};
inline constexpr kane::parameter<14> IB3{};
inline constexpr kane::parameter<15> IB12{};
inline constexpr kane::parameter<16> IB23{};
inline constexpr kane::parameter<17> IB31{};
inline constexpr kane::parameter<18> g{};  // gravity
inline constexpr kane::parameter<19> k{};  // spring
inline constexpr kane::parameter<20> c{};  // damper
inline constexpr kane::parameter<21> d{};  // drag

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::x, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::y, q<2>>> {};
struct O : kane::origin<N> {};
struct Ao : kane::point<O, -lA * kane::constant<1, 2>{} * e<A, 3>> {};
struct J : kane::point<O, -lA * e<A, 3>> {};  // the joint
struct Bo : kane::point<J, -lB * kane::constant<1, 2>{} * e<B, 3>> {};
struct Q : kane::point<J, -lB * e<B, 3>> {};  // the tip

inline constexpr auto joint = (k * kane::q<2> + c * kane::u<2>)*e<A, 2>;
using system =
    kane::system<kane::rigid_body<A, Ao, mA, kane::inertia<A, Ao, IA1, IA2, IA3, IA12, IA23, IA31>>,
                 kane::rigid_body<B, Bo, mB, kane::inertia<B, Bo, IB1, IB2, IB3, IB12, IB23, IB31>>,
                 kane::particle<Q, mQ>, kane::gravity<-g * e<N, 3>>, kane::torque<B, -joint>,
                 kane::torque<A, joint>, kane::force<Q, -d * kane::velocity<N, Q>()>>;
// V = g (mA z_Ao + mB z_Bo + mQ z_Q) + k q2^2 / 2
inline constexpr auto potential =
    g * (mA * dot(kane::position<O, Ao>(), e<N, 3>) + mB * dot(kane::position<O, Bo>(), e<N, 3>) +
         mQ * dot(kane::position<O, Q>(), e<N, 3>)) +
    kane::constant<1, 2>{} * k * kane::q<2> * kane::q<2>;
using state = kane::state<double, 2, 2, 21>;
using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::acceleration, kane::qdot_speeds<2>>;
}  // namespace models::pendulum3d
