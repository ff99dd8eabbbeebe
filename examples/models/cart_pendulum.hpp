// A 3-link pendulum on a cart: the cart at q1 n1 on a horizontal rail, links of
// length l at absolute angles q2, q3, q4 from the downward vertical (frames A1..A3
// about n3), a bob of mass m at the end of each link, the cart of mass mc; gravity
// -g n2. Speeds u = q'. Parameters p1..p4: l, m, mc, g.
#pragma once

#include <kane/kane.hpp>

namespace models::cart_pendulum {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};

struct N : kane::root_frame {};
struct A1 : kane::frame<N, kane::simple<kane::axis::z, q<2>>> {};
struct A2 : kane::frame<N, kane::simple<kane::axis::z, q<3>>> {};
struct A3 : kane::frame<N, kane::simple<kane::axis::z, q<4>>> {};
struct O : kane::origin<N> {};
struct Cart : kane::point<O, kane::q<1> * e<N, 1>> {};
struct P1 : kane::point<Cart, -p<1> * e<A1, 2>> {};
struct P2 : kane::point<P1, -p<1> * e<A2, 2>> {};
struct P3 : kane::point<P2, -p<1> * e<A3, 2>> {};

using system = kane::system<kane::particle<Cart, p<3>>, kane::particle<P1, p<2>>, kane::particle<P2, p<2>>,
                            kane::particle<P3, p<2>>, kane::gravity<-p<4> * e<N, 2>>>;
// V = m g (y1 + y2 + y3)
inline constexpr auto potential =
    p<2> * p<4> *
    (dot(kane::position<O, P1>(), e<N, 2>) + dot(kane::position<O, P2>(), e<N, 2>) +
     dot(kane::position<O, P3>(), e<N, 2>));
using state = kane::state<double, 4, 4, 4>;
using evaluator =
    kane::evaluator<state, kane::frames<A1, A2, A3>, kane::level::acceleration, kane::qdot_speeds<4>>;
}  // namespace models::cart_pendulum
