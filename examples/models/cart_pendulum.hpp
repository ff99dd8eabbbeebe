// A 3-link pendulum on a cart: the cart at q1 n1 on a horizontal rail, links of
// length l at absolute angles q2, q3, q4 from the downward vertical (frames A1..A3
// about n3), a bob of mass m at the end of each link, the cart of mass mc; gravity
// -g n2. Speeds u = q'. Parameters by name, p1..p4 in this order: l, m, mc, g (s[l] = 0.5).
#pragma once

#include <kane/kane.hpp>

namespace models::cart_pendulum {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
inline constexpr kane::parameter<1> l{};   // link length
inline constexpr kane::parameter<2> m{};   // bob mass
inline constexpr kane::parameter<3> mc{};  // cart mass
inline constexpr kane::parameter<4> g{};   // gravity

struct N : kane::root_frame {};
struct A1 : kane::frame<N, kane::simple<kane::axis::z, q<2>>> {};
struct A2 : kane::frame<N, kane::simple<kane::axis::z, q<3>>> {};
struct A3 : kane::frame<N, kane::simple<kane::axis::z, q<4>>> {};
struct O : kane::origin<N> {};
struct Cart : kane::point<O, kane::q<1> * e<N, 1>> {};
struct P1 : kane::point<Cart, -l * e<A1, 2>> {};
struct P2 : kane::point<P1, -l * e<A2, 2>> {};
struct P3 : kane::point<P2, -l * e<A3, 2>> {};

using system = kane::system<kane::particle<Cart, mc>, kane::particle<P1, m>, kane::particle<P2, m>,
                            kane::particle<P3, m>, kane::gravity<-g * e<N, 2>>>;
// V = m g (y1 + y2 + y3)
inline constexpr auto potential =
    m * g *
    (dot(kane::position<O, P1>(), e<N, 2>) + dot(kane::position<O, P2>(), e<N, 2>) +
     dot(kane::position<O, P3>(), e<N, 2>));
using state = kane::state<double, 4, 4, 4>;
using evaluator =
    kane::evaluator<state, kane::frames<A1, A2, A3>, kane::level::acceleration, kane::qdot_speeds<4>>;
}  // namespace models::cart_pendulum
