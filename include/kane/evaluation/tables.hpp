// Numbers of Kane's tables at an evaluator's state:
// partial velocities and remainders (v = sum_r v_r u_r + v_t) and residuals of
// holonomic constraints (nonholonomic_tables.hpp: eq. 20-22). Each column is one
// expression whose zeros are known at compile time (speeds/).
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/wide_stores.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/evaluate_in.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/speeds/constraints.hpp"
#include "kane/speeds/partial_velocity.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// x = T u + t: the table T of the partial velocities (or partial derivatives) and the remainder t.
template <class S, int Rows, int N>
struct linear_result {
  Eigen::Matrix<S, Rows, N> T;
  Eigen::Matrix<S, Rows, 1> t;
};

namespace detail {
template <class Ev>
using speeds_of = std::conditional_t<std::is_void_v<typename Ev::speed_set>, qdot_speeds<Ev::state_type::nq>,
                                     typename Ev::speed_set>;

// x as numbers: a scalar, or a vector in A.
template <class A, class X, class Ev>
KANE_ALWAYS_INLINE auto numbers(const X& x, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (ScalarExpr<X>) {
    return Eigen::Matrix<S, 1, 1>(eval_scalar(x, ev));
  } else {
    const auto r = eval_in<A>(x, ev);
    return Eigen::Matrix<S, 3, 1>(r.x, r.y, r.z);
  }
}

// Column R of T and the remainder t as expressions. An expression of empty
// nodes (every expression without a runtime literal) is differentiated in a
// constant expression: building the derivative then emits no code, at -O0
// too, and the optimiser never sees it.
template <class X>
inline constexpr bool foldable = (std::is_empty_v<X> && std::is_trivially_copyable_v<X>);
template <class Sp, std::size_t R, class X>
constexpr auto column_of(const X& x) {
  if constexpr (foldable<X>) {
    const X y = x;  // copying an empty node reads nothing: usable in a constant expression
    constexpr auto c = column<Sp, R>(y);
    return c;
  } else
    return column<Sp, R>(x);
}
template <class Sp, class X>
constexpr auto remainder_of(const X& x) {
  if constexpr (foldable<X>) {
    const X y = x;
    constexpr auto c = remainder_u<Sp>(y, std::make_index_sequence<Sp::rows>{});
    return c;
  } else
    return remainder_u<Sp>(x, std::make_index_sequence<Sp::rows>{});
}

// Column c of t set to v, three rows in blocks (wide_stores.hpp), as a copy reads them.
template <class T, class V>
KANE_ALWAYS_INLINE void set_column(T& t, Eigen::Index c, const V& v) {
  if constexpr (T::RowsAtCompileTime == 3)
    store_in_blocks<3>(&t(0, c), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { return v(Eigen::Index(i)); });
  else
    t.col(c) = v;
}
// t = [v...] in blocks (wide_stores.hpp): a copy of t reads it in blocks. ByColumn: three rows
// column by column, as a copy into three rows of a taller matrix reads them (J.topRows<3>() = t).
template <bool ByColumn, class T, class... V>
KANE_ALWAYS_INLINE void set_columns(T& t, const V&... v) {
  constexpr std::size_t rows = std::size_t(T::RowsAtCompileTime);
  const auto columns = std::forward_as_tuple(v...);
  if constexpr (ByColumn && rows == 3)
    static_for_inline<sizeof...(V)>(
        [&](auto c) KANE_ALWAYS_INLINE_LAMBDA { set_column(t, Eigen::Index(c), std::get<c>(columns)); });
  else
    store_in_blocks<rows * sizeof...(V)>(t.data(), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
      return std::get<i / rows>(columns)(Eigen::Index(i % rows));
    });
}
// x = T u + t in A: the table T = [v_1 ... v_n] (rows 1 for a scalar x, 3 for
// a vector) and the remainder t, each computed only if asked for. Column r is
// the expression dx/du_r + sum_s dx/dq_s' W_sr, t is x_0 + sum_s dx/dq_s' X_s,
// with the zeros and ones of W and X known at compile time (speeds.hpp). T by column for a caller's
// copy (the entry points below), in blocks for Kane's sums.
template <class A, bool ByColumn, class X, class Ev, class T>
KANE_ALWAYS_INLINE void table_into(const X& x, const Ev& ev, T& t) {
  [&]<std::size_t... R>(std::index_sequence<R...>) KANE_ALWAYS_INLINE_LAMBDA {
    set_columns<ByColumn>(t, numbers<A>(column_of<speeds_of<Ev>, R + 1>(x), ev)...);
  }
  (std::make_index_sequence<speeds_of<Ev>::n>{});
}
template <class A, linear_part Parts, bool ByColumn = false, class X, class Ev>
KANE_ALWAYS_INLINE auto linear_parts_in(const X& x, const Ev& ev) {
  using Sp = speeds_of<Ev>;
  constexpr int rows = ScalarExpr<X> ? 1 : 3;
  Eigen::Matrix<typename Ev::scalar, rows, int(Sp::n)> t;
  Eigen::Matrix<typename Ev::scalar, rows, 1> rest;
  if constexpr (has(Parts, linear_part::table)) table_into<A, ByColumn>(x, ev, t);
  if constexpr (has(Parts, linear_part::remainder)) rest = numbers<A>(remainder_of<Sp>(x), ev);
  if constexpr (Parts == linear_part::both)
    return linear_result<typename Ev::scalar, rows, int(Sp::n)>{t, rest};
  else if constexpr (has(Parts, linear_part::table))
    return t;
  else
    return rest;
}
template <class A, linear_part Parts, class X, class Ev>
requires(inlined_entry<Ev>) KANE_INLINE_FLATTEN auto linear_parts(const X& x, const Ev& ev) {
  return linear_parts_in<A, Parts, true>(x, ev);
}
template <class A, linear_part Parts, class X, class Ev>
requires(!inlined_entry<Ev>) KANE_FLATTEN auto linear_parts(const X& x, const Ev& ev) {
  return linear_parts_in<A, Parts, true>(x, ev);
}
}  // namespace detail

// T and t of x = T u + t in A.
template <Frame A, class X, class Ev>
requires(Evaluator<Ev> && (ScalarExpr<X> || VectorExpr<X>)) auto linear_in_speeds(const X& x, const Ev& ev) {
  return detail::linear_parts<A, detail::linear_part::both>(x, ev);
}

// The table [v_1 ... v_n] in A.
template <Frame A, class X, class Ev>
requires(Evaluator<Ev> && (ScalarExpr<X> || VectorExpr<X>)) auto partial_velocities(const X& x,
                                                                                    const Ev& ev) {
  return detail::linear_parts<A, detail::linear_part::table>(x, ev);
}

// v_t in A.
template <Frame A, class X, class Ev>
requires(Evaluator<Ev> && (ScalarExpr<X> || VectorExpr<X>)) auto remainder(const X& x, const Ev& ev) {
  return detail::linear_parts<A, detail::linear_part::remainder>(x, ev);
}

// f_k at the evaluator's state, and their time derivatives.
template <class Config, Evaluator Ev>
auto residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(std::get<K>(Config::equations), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}
// df_k/dt at the evaluator's state
template <class Config, Evaluator Ev>
auto velocity_residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(Config::template velocity_constraint<K>(), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}

}  // namespace kane
#pragma GCC diagnostic pop
