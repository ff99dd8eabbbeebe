// Partial velocities and partial angular velocities (seed eq. 18-19).
//
// A velocity v (or angular velocity w) is linear in the speeds:
//   v = sum_r v_r u_r + v_t,   v_r = dv/du_r.
// Symbolic: partial_velocity<Speeds>(v, u<r>) is the type-level d/du_r, built
// from dv/dq_s' and dq_s'/du_r = W_sr (type-level 0 or 1 for qdot_speeds, a
// number of the evaluator otherwise); velocity_remainder<Speeds>(v) is v_t.
// Numeric: partial_velocities<A>(v, ev) is the 3 x n table of the v_r
// expressed in A, remainder<A>(v, ev) is v_t in A.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/derivative.hpp"
#include "kane/detail/frame_check.hpp"
#include "kane/evaluator.hpp"
#include "kane/expr.hpp"
#include "kane/speeds.hpp"
#include "kane/vector.hpp"

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

// v_R as an expression: dx/du_R + dx/dq_R' with u = q', else partial_u.
template <class Sp, std::size_t R, class X>
constexpr auto column(X x) {
  if constexpr (Sp::identity)
    return d<speed<R>>(x) + d<coordinate<R, 1>>(x);
  else
    return partial_u<Sp, R>(x, std::make_index_sequence<Sp::n>{});
}

template <class T>
struct is_speed_tag : std::false_type {};
template <std::size_t I>
struct is_speed_tag<speed<I, 0>> : std::true_type {};

template <class Ev>
using speeds_of = std::conditional_t<std::is_void_v<typename Ev::speed_set>, qdot_speeds<Ev::state_type::nq>,
                                     typename Ev::speed_set>;

}  // namespace detail

// v_R = dv/du_R (eq. 18-19), for v a velocity, angular velocity or constraint.
template <SpeedSet Sp, class X, std::size_t R>
requires(ScalarExpr<X> || VectorExpr<X>) constexpr auto partial_velocity(X x, speed<R, 0>) {
  static_assert(R >= 1 && R <= Sp::n, "kane: u_R is not a generalized speed of this system (u_1 .. u_n)");
  return detail::partial_u<Sp, R>(x, std::make_index_sequence<Sp::n>{});
}
// clang-format off
template <SpeedSet Sp, class X, class Leaf> requires(!detail::is_speed_tag<Leaf>::value)
error::partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r<Leaf> partial_velocity(X x, Leaf) = delete;
// clang-format on

// v_t = v - sum_r v_r u_r.
template <SpeedSet Sp, class X>
requires(ScalarExpr<X> || VectorExpr<X>) constexpr auto velocity_remainder(X x) {
  return detail::remainder_u<Sp>(x, std::make_index_sequence<Sp::n>{});
}

namespace detail {
// x as numbers: a scalar, or a vector in A.
template <class A, class X, class Ev>
auto numbers(const X& x, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (ScalarExpr<X>) {
    return Eigen::Matrix<S, 1, 1>(eval_scalar(x, ev));
  } else {
    const auto r = in_frame<A>(eval_vector(x, ev), ev);
    return Eigen::Matrix<S, 3, 1>(r.x, r.y, r.z);
  }
}

// x = T u + t in A: the table T = [v_1 ... v_n] (rows 1 for a scalar x, 3 for
// a vector) and the remainder t, each computed only if asked for. Column r is
// the expression dx/du_r + sum_s dx/dq_s' W_sr, t is x_0 + sum_s dx/dq_s' X_s,
// with the zeros and ones of W and X known at compile time (speeds.hpp).
template <class A, bool Table, bool Rest, class X, class Ev>
KANE_FLATTEN auto linear_parts(const X& x, const Ev& ev) {
  using Sp = speeds_of<Ev>;
  constexpr int rows = ScalarExpr<X> ? 1 : 3;
  Eigen::Matrix<typename Ev::scalar, rows, int(Sp::n)> t;
  Eigen::Matrix<typename Ev::scalar, rows, 1> rest;
  [&]<std::size_t... R>(std::index_sequence<R...>) {
    if constexpr (Table) ((t.col(R) = numbers<A>(column<Sp, R + 1>(x), ev)), ...);
    if constexpr (Rest) rest = numbers<A>(remainder_u<Sp>(x, std::make_index_sequence<Sp::n>{}), ev);
  }
  (std::make_index_sequence<Sp::n>{});
  if constexpr (Table && Rest)
    return std::pair{t, rest};
  else if constexpr (Table)
    return t;
  else
    return rest;
}
}  // namespace detail

// The pair (T, t) of x = T u + t in A.
template <Frame A, class X, class Ev>
requires(detail::is_evaluator<Ev>::value &&
         (ScalarExpr<X> || VectorExpr<X>)) auto linear_in_speeds(const X& x, const Ev& ev) {
  return detail::linear_parts<A, true, true>(x, ev);
}

// The table [v_1 ... v_n] in A.
template <Frame A, class X, class Ev>
requires(detail::is_evaluator<Ev>::value &&
         (ScalarExpr<X> || VectorExpr<X>)) auto partial_velocities(const X& x, const Ev& ev) {
  return detail::linear_parts<A, true, false>(x, ev);
}

// v_t in A.
template <Frame A, class X, class Ev>
requires(detail::is_evaluator<Ev>::value && (ScalarExpr<X> || VectorExpr<X>)) auto remainder(const X& x,
                                                                                             const Ev& ev) {
  return detail::linear_parts<A, false, true>(x, ev);
}

}  // namespace kane
