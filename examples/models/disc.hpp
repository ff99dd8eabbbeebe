// The rolling disc, shared by the example, the tests and the benchmarks: yaw q1
// about n3 (frame Y), lean q2 about y1 (L), spin q3 about l2 (R, the disc);
// radius r = p1. Speeds: u_i = ^N w^R . l_i.
// Three coordinates: rolling without slip makes the contact point's velocity
// zero, so the centre moves with ^N w^R x r l3.
// Five coordinates: the contact point at q4 n1 + q5 n2, u4 = q4', u5 = q5';
// two nonholonomic constraints (the disc's contact point is at rest in N)
// make u4, u5 dependent. The dynamics: a uniform thin disc of mass m under gravity g.
#pragma once

#include <kane/kane.hpp>

namespace models::disc {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct r_ : kane::parameter<1> {};
struct m_ : kane::parameter<2> {};
struct g_ : kane::parameter<3> {};
inline constexpr r_ r;
inline constexpr m_ m;
inline constexpr g_ g;

struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};  // yaw
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};  // lean
struct R : kane::frame<L, kane::simple<kane::axis::y, q<3>>> {};  // spin: the disc

inline constexpr auto w = kane::angular_velocity<N, R>();
using speeds3 = kane::speeds<dot(w, e<L, 1>), dot(w, e<L, 2>), dot(w, e<L, 3>)>;

struct C : kane::origin<N> {};  // the contact point, at rest
struct Centre : kane::point<C, r * e<L, 3>> {};
inline constexpr auto v_centre = kane::body_point_velocity<N, R, C, Centre>();

struct O : kane::origin<N> {};
struct Contact : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2>> {};
struct Centre5 : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre5, -r * e<L, 3>> {};  // the disc's point at the contact
using speeds5 = kane::angular_velocity_speeds<N, R, L, kane::dt(kane::q<4>), kane::dt(kane::q<5>)>;
inline constexpr auto v_below = kane::body_point_velocity<N, R, Centre5, Below>();
using rolling =
    kane::nonholonomic<speeds5, kane::dependent<4, 5>, dot(v_below, e<N, 1>), dot(v_below, e<N, 2>)>;
// The disc's dynamics: mass m (p2), inertia m r^2/4 about r1, r3 and m r^2/2 about r2, gravity g (p3).
inline constexpr auto diametral = kane::constant<1, 4>{} * m * r * r;
using system = kane::system<
    kane::rigid_body<R, Centre5, m, kane::inertia<R, Centre5, diametral, 2 * diametral, diametral>>,
    kane::gravity<-g * e<N, 3>>>;
inline constexpr auto height = dot(kane::position<O, Centre5>(), e<N, 3>);  // V = m g height
// The same disc with three coordinates: its centre known by its velocity alone, ^N w^R x r l3.
struct Centre3 : kane::point_by_velocity<N, v_centre> {};
using system3 = kane::system<
    kane::rigid_body<R, Centre3, m, kane::inertia<R, Centre3, diametral, 2 * diametral, diametral>>,
    kane::gravity<-g * e<N, 3>>>;
}  // namespace models::disc
