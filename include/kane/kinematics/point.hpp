// Points, their velocities and accelerations.
//
//   struct O : kane::origin<N> {};                           // fixed in N
//   struct P : kane::point<O, L1 * kane::e<A, 1>> {};         // r^OP = L1 a1
//   kane::velocity<N, P>()      ^N v^P = ^N d r^QP/dt, Q fixed in N on P's chain
//   kane::acceleration<N, P>()  ^N a^P = ^N d(^N v^P)/dt
//   struct D : kane::point_by_velocity<N, v> {};             // ^N v^D = v, no position
//
// A point is fixed in A if it is an origin of A, or if its position from a
// point fixed in A has a zero A-derivative (decided at compile time); the
// velocity in A of a point fixed in A is the zero vector as a type.
#pragma once

#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct point_tag {};
}  // namespace detail

template <class P>
concept Point = std::derived_from<P, detail::point_tag>;

// A root point, fixed in F.
template <Frame F>
struct origin : detail::point_tag {
  // void: a root point is located from no point
  using from = void;
  // F, the frame the point is fixed in
  using fixed_frame = F;
  // the zero vector: no position from another point
  static constexpr zero_vector position{};
};

// A point known by its velocity in A alone (a mass centre whose velocity a textbook gives:
// a rolling disc's centre, w x r): ^A v^P = V, ^A a^P = ^A dV/dt. V is the velocity of the
// point itself; points located from P have ^A v = V + ^A d r/dt. P has no position from
// points of other chains, and no velocity in frames other than A.
template <Frame A, auto Velocity>
struct point_by_velocity : detail::point_tag {
  static_assert(VectorExpr<decltype(Velocity)>, "kane: point_by_velocity<A, v> needs a vector expression v");
  static_assert(detail::check<!is_zero_vector_v<std::remove_cvref_t<decltype(Velocity)>>,
                              error::a_point_at_rest_is_an_origin_write_kane_origin_of_the_frame<A>>);
  // void: located from no point
  using from = void;
  // void: no frame the point is fixed in
  using fixed_frame = void;  // fixed in no frame
  // A, the one frame the velocity is known in
  using velocity_frame = A;
  // the zero vector: no position from another point
  static constexpr zero_vector position{};
  // Velocity: ^A v^P
  static constexpr auto known_velocity = detail::freeze<Velocity>();
};

// A point located from the point From by the vector Position (r^{From, this}).
template <class From, auto Position>
struct point : detail::point_tag {
  static_assert(Point<From>, "kane: point<From, r> needs a point From (kane::origin or kane::point)");
  static_assert(VectorExpr<decltype(Position)>, "kane: point<From, r> needs a vector expression r");
  // From, the point this one is located from
  using from = From;
  // Position: r^{From, this}
  static constexpr auto position = detail::freeze<Position>();
};

// ^A v^P and ^A a^P: a vector expression that remembers its frame and point.
template <class A, class P, class V>
struct velocity_of : detail::quantity_tag {
  // A, the frame of the velocity
  using observer = A;
  // the expression of ^A v^P
  [[no_unique_address]] V v;
  // ^A v^P given by x
  constexpr explicit velocity_of(V x) : v(x) {}
};
// ^A a^P, a vector expression that remembers its observer and point.
template <class A, class P, class V>
struct acceleration_of : detail::quantity_tag {
  // A, the frame of the acceleration
  using observer = A;
  // the expression of ^A a^P
  [[no_unique_address]] V v;
  // ^A a^P given by x
  constexpr explicit acceleration_of(V x) : v(x) {}
};

namespace detail {
template <class A, class P, class V>
struct some_frame<velocity_of<A, P, V>> {
  using type = A;
};
template <class A, class P, class V>
struct some_frame<acceleration_of<A, P, V>> {
  using type = A;
};

// list<P, from of P, ..., origin>
template <class P, class From = typename P::from>
struct point_chain {
  using type = typename push_front<P, typename point_chain<From>::type>::type;
};
template <class P>
struct point_chain<P, void> {
  using type = list<P>;
};

template <class... P>
constexpr auto sum_positions(list<P...>) {
  return (P::position + ... + zero_vector{});  // right fold: the tails are the sums from each point on
}

template <class P, class A>
constexpr bool fixed_in() {
  if constexpr (std::is_void_v<typename P::from>)
    return std::is_same_v<typename P::fixed_frame, A>;
  else if constexpr (!fixed_in<typename P::from, A>())
    return false;
  else
    return is_zero_vector_v<decltype(ddt_in<A>(P::position))>;
}

template <class P>
inline constexpr bool by_velocity = requires {
  typename P::velocity_frame;
};
template <class L>
struct last;
template <class... P>
struct last<list<P...>> {
  using type = typename decltype((std::type_identity<P>{}, ...))::type;
};
template <class P>
using chain_root_t = typename last<typename point_chain<P>::type>::type;

// The first point of L fixed in A, or void.
template <class L, class A>
struct first_fixed {
  using type = void;
};
template <class H, class... T, class A>
struct first_fixed<list<H, T...>, A> {
  using type = std::conditional_t<fixed_in<H, A>(), H, typename first_fixed<list<T...>, A>::type>;
};

template <class A, class P, class V>
constexpr auto measured_velocity(V v) {
  if constexpr (is_zero_vector_v<V>)
    return v;
  else
    return velocity_of<A, P, V>(v);
}
template <class A, class P, class V>
constexpr auto measured_acceleration(V v) {
  if constexpr (is_zero_vector_v<V>)
    return v;
  else
    return acceleration_of<A, P, V>(v);
}
}  // namespace detail

// position, velocity and acceleration hold their expression in a constexpr
// variable: the expression is built by the constant evaluator, so no function
// of its construction is compiled (at -O0 each would be).

// r^PQ, the position of Q from P.
template <Point P, Point Q>
constexpr auto position() {
  using cp = typename detail::point_chain<P>::type;
  using cq = typename detail::point_chain<Q>::type;
  using X = typename detail::first_common<cp, cq>::type;
  constexpr bool joined = !std::is_void_v<X>;
  constexpr bool moving =
      detail::by_velocity<detail::chain_root_t<P>> || detail::by_velocity<detail::chain_root_t<Q>>;
  static_assert(
      detail::check<(joined || !moving),
                    error::a_point_known_by_its_velocity_has_no_position_locate_points_from_it<P, Q>>);
  static_assert(
      detail::check<(joined || moving), error::points_not_joined_locate_both_from_one_origin<P, Q>>);
  if constexpr (std::is_void_v<X>)
    return zero_vector{};
  else {
    constexpr auto r =
        detail::sum_positions(typename detail::reverse<typename detail::before<cq, X>::type>::type{}) -
        detail::sum_positions(typename detail::reverse<typename detail::before<cp, X>::type>::type{});
    return r;
  }
}

// P is fixed in A
template <Point P, Frame A>
inline constexpr bool fixed_in_v = detail::fixed_in<P, A>();

// ^A v^P (eq. 15).
template <Frame A, Point P>
constexpr auto velocity(P = {}) {
  using Q = typename detail::first_fixed<typename detail::point_chain<P>::type, A>::type;
  using O = detail::chain_root_t<P>;
  // an origin<A>, or a point whose position from one is constant in A; or a point known by its
  // velocity in A
  if constexpr (std::is_void_v<Q> && detail::by_velocity<O>) {
    static_assert(
        detail::check<std::is_same_v<typename O::velocity_frame, A>,
                      error::the_velocity_of_this_point_is_known_in_another_frame_observe_it_there<A, P>>);
    constexpr auto v =
        detail::measured_velocity<A, P>(O::known_velocity + detail::ddt_in<A>(position<O, P>()));
    return v;
  } else {
    static_assert(
        detail::check<!std::is_void_v<Q>,
                      error::no_point_of_the_chain_is_fixed_in_the_observer_locate_the_point_from_one<A, P>>);
    if constexpr (std::is_void_v<Q>)
      return zero_vector{};
    else {
      constexpr auto v = detail::measured_velocity<A, P>(detail::ddt_in<A>(position<Q, P>()));
      return v;
    }
  }
}

// ^A a^P = ^A d(^A v^P)/dt (eq. 15).
template <Frame A, Point P>
constexpr auto acceleration(P = {}) {
  constexpr auto a = detail::measured_acceleration<A, P>(detail::ddt_in<A>(velocity<A, P>()));
  return a;
}

// Two points P, Q fixed in B: ^A v^P = ^A v^Q + ^A w^B x r^QP. Checked at
// compile time: r^QP has a zero B-derivative.
template <Frame A, Frame B, Point Q, Point P>
constexpr auto two_point_velocity() {
  constexpr auto r = position<Q, P>();
  static_assert(
      detail::check<
          is_zero_vector_v<decltype(detail::ddt_in<B>(r))>,
          error::two_point_theorem_needs_both_points_fixed_in_the_body_use_one_point_velocity<B, Q, P>>);
  return detail::measured_velocity<A, P>(velocity<A, Q>() + cross(angular_velocity<A, B>(), r));
}
// ^A a^P = ^A a^Q + ^A alpha^B x r^QP + ^A w^B x (^A w^B x r^QP).
template <Frame A, Frame B, Point Q, Point P>
constexpr auto two_point_acceleration() {
  constexpr auto r = position<Q, P>();
  static_assert(
      detail::check<
          is_zero_vector_v<decltype(detail::ddt_in<B>(r))>,
          error::two_point_theorem_needs_both_points_fixed_in_the_body_use_one_point_velocity<B, Q, P>>);
  constexpr auto w = angular_velocity<A, B>();
  return detail::measured_acceleration<A, P>(acceleration<A, Q>() + cross(angular_acceleration<A, B>(), r) +
                                             cross(w, cross(w, r)));
}
// P moving on B, Q fixed in B: ^A v^P = ^A v^Q + ^B v^P + ^A w^B x r^QP, with
// ^B v^P = ^B d r^QP/dt (the identity holds for any Q; Q fixed in B makes it
// the one-point theorem).
template <Frame A, Frame B, Point Q, Point P>
constexpr auto one_point_velocity() {
  constexpr auto r = position<Q, P>();
  return detail::measured_velocity<A, P>(velocity<A, Q>() + detail::ddt_in<B>(r) +
                                         cross(angular_velocity<A, B>(), r));
}
// ^A a^P = ^A a^Q + ^B a^P + 2 ^A w^B x ^B v^P + ^A alpha^B x r + ^A w^B x (^A w^B x r).
template <Frame A, Frame B, Point Q, Point P>
constexpr auto one_point_acceleration() {
  constexpr auto r = position<Q, P>();
  constexpr auto w = angular_velocity<A, B>();
  constexpr auto vB = detail::ddt_in<B>(r);
  return detail::measured_acceleration<A, P>(acceleration<A, Q>() + detail::ddt_in<B>(vB) +
                                             constant<2>{} * cross(w, vB) +
                                             cross(angular_acceleration<A, B>(), r) + cross(w, cross(w, r)));
}

// The velocity in A of the point of body B at P, given Q a point of B:
// ^A v^Q + ^A w^B x r^QP. That Q belongs to B is the caller's statement (for
// a rolling contact, Q may be the contact point, whose velocity is zero).
template <Frame A, Frame B, Point Q, Point P>
constexpr auto body_point_velocity() {
  return velocity<A, Q>() + cross(angular_velocity<A, B>(), position<Q, P>());
}

}  // namespace kane
#pragma GCC diagnostic pop
