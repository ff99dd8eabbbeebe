// A floating base on Euler parameters with body rates, carrying two spatial arms of `links` links
// (one link: 9 coordinates, 8 speeds; eight: 23 and 22). A free body is not of joint form, so its
// dynamics take Kane's sums and its linearization jets in batches. Inputs: a thrust along b3 and a
// torque pair at each shoulder.
#pragma once

#include <cstddef>
#include <type_traits>

#include <kane/kane.hpp>

namespace floating_arms {
using kane::dot;
using kane::dt;
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;
inline constexpr std::size_t links = 1;

struct N : kane::root_frame {};
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::position_coordinates<N, 5>> {};

constexpr double length(std::size_t k) { return 0.12 + 0.03 * double((k * 5) % 4); }
constexpr double mass(std::size_t k) { return 0.5 + 0.15 * double((k * 3) % 5); }
template <std::size_t K>
using axis_of = std::conditional_t<K % 3 == 1, kane::axis::z,
                                   std::conditional_t<K % 3 == 2, kane::axis::y, kane::axis::x>>;
// link K (1 .. links) of arm A (0, 1), turned by q_(7 + links A + K) about z, y, x, ... of the link before
template <std::size_t A, std::size_t K>
struct L;
template <std::size_t A, std::size_t K>
using parent = std::conditional_t<K == 1, B, L<A, K - 1>>;
template <std::size_t A, std::size_t K>
struct L : kane::frame<parent<A, K>, kane::simple<axis_of<K>, q<7 + links * A + K>>> {};
// joint K of arm A: the shoulder at -+0.25 b2 from the base's centre, then along x of each link
template <std::size_t A, std::size_t K>
struct J : kane::point<J<A, K - 1>, literal(length(K - 1)) * e<L<A, K - 1>, 1>> {};
template <std::size_t A>
struct J<A, 1> : kane::point<Bo, literal(A == 0 ? -0.25 : 0.25) * e<B, 2>> {};
template <std::size_t A, std::size_t K>
struct C : kane::point<J<A, K>, literal(length(K) / 2) * e<L<A, K>, 1> + literal(0.01) * e<L<A, K>, 3>> {};
template <std::size_t A, std::size_t K>
using link =
    kane::rigid_body<L<A, K>, C<A, K>, literal(mass(K)),
                     kane::inertia<L<A, K>, C<A, K>, literal(0.004 * mass(K)), literal(0.006 * mass(K)),
                                   literal(0.007 * mass(K)), literal(0.0004 * mass(K)),
                                   literal(-0.0003 * mass(K)), literal(0.0002 * mass(K))>>;
using base =
    kane::rigid_body<B, Bo, literal(6.0),
                     kane::inertia<B, Bo, literal(0.08), literal(0.05), literal(0.1), literal(0.004)>>;

template <class>
struct items;
template <std::size_t... K>
struct items<std::index_sequence<K...>> {
  using type =
      kane::system<base, link<0, K + 1>..., link<1, K + 1>..., kane::gravity<literal(-9.81) * e<N, 3>>,
                   kane::force<Bo, kane::r<1> * e<B, 3>>,  // thrust
                   kane::torque<L<0, 1>, kane::r<2> * e<B, 3>>, kane::torque<B, -kane::r<2> * e<B, 3>>,
                   kane::torque<L<1, 1>, kane::r<3> * e<B, 3>>, kane::torque<B, -kane::r<3> * e<B, 3>>>;
};
using system = typename items<std::make_index_sequence<links>>::type;

inline constexpr auto w = kane::angular_velocity<N, B>();
template <class>
struct speed_set;
template <std::size_t... I>  // body rates, the centre's q5' .. q7', every joint's q'
struct speed_set<std::index_sequence<I...>> {
  using type =
      kane::speeds<dot(w, e<B, 1>), dot(w, e<B, 2>), dot(w, e<B, 3>), dt(q<5 + I>{})..., kane::unit_norm<B>>;
};
using speeds = typename speed_set<std::make_index_sequence<3 + 2 * links>>::type;
using state = kane::state_of<system, speeds>;
using evaluator = kane::system_evaluator<system, speeds>;
using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>>;
}  // namespace floating_arms
