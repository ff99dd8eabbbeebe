// Partial velocities and partial angular velocities.
//
// A velocity v (or angular velocity w) is linear in the speeds:
//   v = sum_r v_r u_r + v_t,   v_r = dv/du_r.
// Symbolic: partial_velocity<Speeds>(v, u<r>) is the type-level d/du_r, built
// from dv/dq_s' and dq_s'/du_r = W_sr (type-level 0 or 1 for qdot_speeds, a
// number of the evaluator otherwise); velocity_remainder<Speeds>(v) is v_t.
// Their numbers at a state: evaluation/tables.hpp.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/frame_check.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/speeds/kinematic_weights.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

// dx/dLeaf for a scalar or a vector (a derivative by q', u or t is the same in every frame).
template <class Leaf, class X>
constexpr auto d(X x) {
  if constexpr (ScalarExpr<X>)
    return partial<Leaf>(x);
  else
    return partial_in<root_frame_of_t<X>, Leaf>(x);
}

template <class Sp, std::size_t R, class X, std::size_t... S>
constexpr auto partial_u(X x, std::index_sequence<S...>) {
  return (d<speed<R>>(x) + ... + (d<coordinate<S + 1, 1>>(x) * weight<Sp, S + 1, R>()));
}
template <class Sp, class X, std::size_t... S>
constexpr auto remainder_u(X x, std::index_sequence<S...>) {
  if constexpr (Sp::identity)
    return at_rest(x);
  else
    return (at_rest(x) + ... + (d<coordinate<S + 1, 1>>(x) * offset<Sp, S + 1>()));
}

// The nearest of F and its ancestors whose angular velocity the speeds give (void: none).
template <class Sp, class List>
struct component_body {
  using type = void;
};
template <class Sp, class F, class... Up>
struct component_body<Sp, list<F, Up...>> {
  using type =
      std::conditional_t<(component_speeds<Sp, F>() > 0), F, typename component_body<Sp, list<Up...>>::type>;
};
template <class Sp>
inline constexpr bool has_component_speeds = !Sp::identity && Sp::defined >= 3;

// d(^R w^F)/du_R with the speeds of a rate body B above F: f_i of B, then the edges from B to F.
template <class Sp, std::size_t R, class F, std::size_t... S>
constexpr auto omega_column(std::index_sequence<S...> s) {
  using B = typename component_body<Sp, typename ancestors<F>::type>::type;
  if constexpr (std::is_void_v<B>)
    return partial_u<Sp, R>(omega<F>{}, s);
  else {
    constexpr std::size_t k = component_speeds<Sp, B>();
    using G = typename component_row<row_t<Sp, k - 1>>::frame;
    using p = path<B, F>;
    const auto own = [] {
      if constexpr (R >= k && R < k + 3)
        return unit<G, int(R - k + 1)>{};
      else
        return zero_vector{};
    }();
    return ((own + partial_omega<R, wrt::speeds>(typename p::up{}, typename p::down{})) + ... +
            (partial_omega<S + 1>(typename p::up{}, typename p::down{}) * weight<Sp, S + 1, R>()));
  }
}
// v_R of a vector, term by term where the speeds give an angular velocity (omega_column).
template <class Sp, std::size_t R, class X>
constexpr auto rate_column(X x) {
  constexpr auto rows = std::make_index_sequence<Sp::rows>{};
  if constexpr (ScalarExpr<X> || is_zero_vector_v<X>)
    return partial_u<Sp, R>(x, rows);
  else if constexpr (is_unit<X>::value)
    return zero_vector{};
  else if constexpr (is_v<X, scaled>)
    return partial_u<Sp, R>(x.s, rows) * x.v + x.s * rate_column<Sp, R>(x.v);
  else if constexpr (is_v<X, vsum>)
    return rate_column<Sp, R>(x.l) + rate_column<Sp, R>(x.r);
  else if constexpr (is_v<X, vdiff>)
    return rate_column<Sp, R>(x.l) - rate_column<Sp, R>(x.r);
  else if constexpr (is_v<X, vneg>)
    return -rate_column<Sp, R>(x.v);
  else if constexpr (is_v<X, vcross>)
    return derived_cross(rate_column<Sp, R>(x.l), x.r) + derived_cross(x.l, rate_column<Sp, R>(x.r));
  else if constexpr (is_v<X, omega>)
    return omega_column<Sp, R, typename X::frame>(rows);
  else if constexpr (is_v<X, angular_velocity_of>)
    return rate_column<Sp, R>(expand(x));
  else if constexpr (Quantity<X>)
    return rate_column<Sp, R>(x.v);
  else
    return partial_u<Sp, R>(x, rows);
}

// v_R as an expression: dx/du_R + dx/dq_R' with u = q', else partial_u (rate_column where
// the speeds give angular velocities).
template <class Sp, std::size_t R, class X>
constexpr auto column(X x) {
  if constexpr (Sp::identity)
    return d<speed<R>>(x) + d<coordinate<R, 1>>(x);
  else if constexpr (has_component_speeds<Sp> && VectorExpr<X>)
    return rate_column<Sp, R>(x);
  else
    return partial_u<Sp, R>(x, std::make_index_sequence<Sp::rows>{});
}

}  // namespace detail

// v_R = dv/du_R (eq. 18-19), for v a velocity, angular velocity or constraint.
template <SpeedSet Sp, class X, std::size_t R>
requires(ScalarExpr<X> || VectorExpr<X>) constexpr auto partial_velocity(X x, speed<R, 0>) {
  static_assert(R >= 1 && R <= Sp::n, "kane: u_R is not a generalized speed of this system (u_1 .. u_n)");
  return detail::partial_u<Sp, R>(x, std::make_index_sequence<Sp::rows>{});
}
// v_L for a leaf L that is not a speed: an error
template <SpeedSet Sp, class X, class Leaf>
requires(!Speed<Leaf>) constexpr X partial_velocity(X x, Leaf) {
  static_assert(
      detail::refused<error::partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r<Leaf>>);
  return x;
}

// v_t = v - sum_r v_r u_r, times kane::speed_set_one<Sp>: only an evaluator of Sp reads it.
template <SpeedSet Sp, class X>
requires(ScalarExpr<X> || VectorExpr<X>) constexpr auto velocity_remainder(X x) {
  const auto r = detail::remainder_u<Sp>(x, std::make_index_sequence<Sp::rows>{});
  if constexpr (ScalarExpr<decltype(r)>)
    return mul<speed_set_one<Sp>, decltype(r)>(speed_set_one<Sp>{}, r);
  else
    return scaled<speed_set_one<Sp>, decltype(r)>(speed_set_one<Sp>{}, r);
}

}  // namespace kane
#pragma GCC diagnostic pop
