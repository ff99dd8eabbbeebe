// Numbers of Kane's tables at an evaluator's state (seed eq. 16-22):
// partial velocities and remainders (v = sum_r v_r u_r + v_t), residuals of
// holonomic constraints, u_dep = A u_ind + B of nonholonomic constraints and
// the nonholonomic partial velocities. Each column is one expression whose
// zeros are known at compile time (speeds/).
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/evaluate_in.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/speeds/constraints.hpp"
#include "kane/speeds/partial_velocity.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
template <class Ev>
using speeds_of = std::conditional_t<std::is_void_v<typename Ev::speed_set>, qdot_speeds<Ev::state_type::nq>,
                                     typename Ev::speed_set>;

// The evaluator's speed set is the constraints'; a solution is of these constraints.
template <class Ev, class NH>
inline constexpr bool same_speeds_v =
    check<std::is_same_v<speeds_of<Ev>, typename NH::speed_set>,
          error::evaluator_and_constraints_use_different_speed_sets<speeds_of<Ev>, typename NH::speed_set>>;
template <class Sol, class NH>
inline constexpr bool solution_of_v =
    check<std::is_same_v<typename Sol::constraints, NH>,
          error::constraint_solution_of_other_constraints_solve_these<typename Sol::constraints, NH>>;
}  // namespace detail

namespace detail {
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

// x = T u + t in A: the table T = [v_1 ... v_n] (rows 1 for a scalar x, 3 for
// a vector) and the remainder t, each computed only if asked for. Column r is
// the expression dx/du_r + sum_s dx/dq_s' W_sr, t is x_0 + sum_s dx/dq_s' X_s,
// with the zeros and ones of W and X known at compile time (speeds.hpp).
// Column c of t set to v: for doubles the first two numbers as one 16-byte store, since the
// copy that reads them next (into the caller's matrix) reads them as one, and a wide load of
// two narrow stores waits for both to leave the store buffer.
template <class T, class V>
KANE_ALWAYS_INLINE void set_column(T& t, Eigen::Index c, const V& v) {
  if constexpr (std::is_same_v<typename T::Scalar, double> && T::RowsAtCompileTime == 3) {
    using pair = double __attribute__((vector_size(16)));
    const pair xy = {v(0), v(1)};
    std::memcpy(&t(0, c), &xy, sizeof xy);
    t(2, c) = v(2);
  } else
    t.col(c) = v;
}
template <class A, bool Table, bool Rest, class X, class Ev>
KANE_ALWAYS_INLINE auto linear_parts_in(const X& x, const Ev& ev) {
  using Sp = speeds_of<Ev>;
  constexpr int rows = ScalarExpr<X> ? 1 : 3;
  Eigen::Matrix<typename Ev::scalar, rows, int(Sp::n)> t;
  Eigen::Matrix<typename Ev::scalar, rows, 1> rest;
  [&]<std::size_t... R>(std::index_sequence<R...>) {
    if constexpr (Table) (set_column(t, Eigen::Index(R), numbers<A>(column_of<Sp, R + 1>(x), ev)), ...);
    if constexpr (Rest) rest = numbers<A>(remainder_of<Sp>(x), ev);
  }
  (std::make_index_sequence<Sp::n>{});
  if constexpr (Table && Rest)
    return std::pair{t, rest};
  else if constexpr (Table)
    return t;
  else
    return rest;
}
template <class A, bool Table, bool Rest, class X, class Ev>
requires(inlined_entry<Ev>) KANE_INLINE_FLATTEN auto linear_parts(const X& x, const Ev& ev) {
  return linear_parts_in<A, Table, Rest>(x, ev);
}
template <class A, bool Table, bool Rest, class X, class Ev>
requires(!inlined_entry<Ev>) KANE_FLATTEN auto linear_parts(const X& x, const Ev& ev) {
  return linear_parts_in<A, Table, Rest>(x, ev);
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

// f_k at the evaluator's state, and their time derivatives.
template <class Config, class Ev>
auto residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(std::get<K>(Config::equations), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}
// df_k/dt at the evaluator's state
template <class Config, class Ev>
auto velocity_residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(Config::template velocity_constraint<K>(), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}

// u_dep = A u_ind + B at a state; status is ok only if the evaluator's status
// is ok and the dependent block was solvable with finite A and B (it is the
// evaluator's status when that failed, as for NaN in the state; A and B are
// NaN whenever status is not ok).
// C and c0 are the constraints solved, C u + c0 = 0 (C: M x (M + P), all speeds).
template <class S, std::size_t M, std::size_t P, class NH = void>
struct constraint_solution {
  // NH, the constraints solved
  using constraints = NH;  // the declaration solved: tables of other constraints refuse it
  // A of u_dep = A u_ind + B
  Eigen::Matrix<S, int(M), int(P)> A;
  // B of u_dep = A u_ind + B
  Eigen::Matrix<S, int(M), 1> B;
  // ok, or why A and B are NaN
  solve_status status;
  // C of C u + c0 = 0: M x (M + P), all speeds
  Eigen::Matrix<S, int(M), int(M + P)> C;
  // c0 of C u + c0 = 0
  Eigen::Matrix<S, int(M), 1> c0;
  // the block of C at the dependent speeds, factored
  detail::factored<S, M> dependent;  // the block of C of the dependent speeds: u_dep' reuses it
};

// u_dep = A u_ind + B at the evaluator's state.
template <class NH, class Ev>
KANE_INLINE_FLATTEN auto solve_constraints(const Ev& ev) {
  using S = typename Ev::scalar;
  using Sys = detail::constraint_system<NH>;
  static_assert(detail::same_speeds_v<Ev, NH>);
  static_assert(Sys::form.regular,
                "kane: the constraints do not determine the dependent speeds (their block of coefficients is "
                "singular at every state); choose dependent speeds that the constraints involve");
  constexpr std::size_t m = NH::m, p = NH::p;
  detail::table<S, m, m> dep{};  // zeros where the structure leaves entries unread
  detail::table<S, m, p + 1> right{}, x;
  [&]<std::size_t... I, std::size_t... J>(std::index_sequence<I...>, std::index_sequence<J...>) {
    detail::with_common_subexpressions<decltype(Sys::template coefficient<I / m, NH::dependents[I % m]>())...,
                                       decltype(Sys::template right<J / (p + 1), J % (p + 1)>())...>(
        ev, [&](const auto& e) {
          detail::static_for<m * m>([&](auto kj) {
            constexpr std::size_t k = kj / m, j = kj % m;
            if constexpr (Sys::m[k][j] == detail::entry::other) {
              constexpr auto c =
                  Sys::template coefficient<k, NH::dependents[j]>();  // built by the constant evaluator
              dep[k][j] = detail::eval_scalar(c, e);
            }
          });
          detail::static_for<m*(p + 1)>([&](auto kj) {
            constexpr std::size_t k = kj / (p + 1), j = kj % (p + 1);
            if constexpr (Sys::r[k][j] == detail::entry::other) {
              constexpr auto c = Sys::template right<k, j>();
              right[k][j] = detail::eval_scalar(c, e);
            }
          });
        });
  }
  (std::make_index_sequence<m * m>{}, std::make_index_sequence<m*(p + 1)>{});
  constraint_solution<S, m, p, NH> out;
  detail::static_for<m * m>([&](auto kj) {
    constexpr std::size_t k = kj / m, j = kj % m;
    out.C(Eigen::Index(k), Eigen::Index(NH::dependents[j] - 1)) =
        Sys::m[k][j] == detail::entry::one ? S(1) : dep[k][j];
  });
  detail::static_for<m*(p + 1)>([&](auto kj) {
    constexpr std::size_t k = kj / (p + 1), j = kj % (p + 1);
    const S c = Sys::r[k][j] == detail::entry::one ? S(1) : right[k][j];
    if constexpr (j < p)
      out.C(Eigen::Index(k), Eigen::Index(NH::independents[j] - 1)) = c;
    else
      out.c0(Eigen::Index(k)) = c;
  });
  out.dependent.m = dep;
  out.dependent.factors = detail::factor_structured<Sys>(dep);
  const solve_status solved = detail::substitute_structured<Sys>(dep, out.dependent.factors, right, x);
  out.status = ev.status() != solve_status::ok ? ev.status() : solved;
  for (std::size_t k = 0; k < m; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    for (std::size_t j = 0; j < p; ++j) out.A(row, static_cast<Eigen::Index>(j)) = -x[k][j];
    out.B(row) = -x[k][p];
  }
  const auto spoil = detail::nan_unless<S>(out.status == solve_status::ok);
  spoil(out.A);
  spoil(out.B);
  return out;
}

namespace detail {
// col += a v in F; a v_r that is +-e_Fi adds to one component.
template <class F, class V>
constexpr bool unit_of() {  // V is e_Fi
  if constexpr (is_unit<V>::value)
    return std::is_same_v<typename V::frame, F>;
  else
    return false;
}
template <class F, class V, class Col, class S, class Ev>
void add_scaled(Col& col, const V& v, S a, const Ev& ev) {
  if constexpr (is_zero_v<V> || is_zero_vector_v<V>)
    return;
  else if constexpr (unit_of<F, V>())
    col(V::index - 1) += a;
  else if constexpr (is_vneg<V>::value) {
    if constexpr (unit_of<F, decltype(v.v)>())
      col(decltype(v.v)::index - 1) -= a;
    else
      col += numbers<F>(v, ev) * a;
  } else
    col += numbers<F>(v, ev) * a;
}
}  // namespace detail

// [v~_1 ... v~_p] in F: v~_s = v_s + sum_r v_r A_rs over the independent s.
template <Frame F, class NH, class X, class Ev, class Sol>
KANE_INLINE_FLATTEN auto nonholonomic_partial_velocities(const X& x, const Ev& ev, const Sol& sol) {
  using S = typename Ev::scalar;
  using Sp = typename NH::speed_set;
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  Eigen::Matrix<S, ScalarExpr<X> ? 1 : 3, int(NH::p)> out;
  detail::static_for<NH::p>([&](auto k) {
    auto col = detail::numbers<F>(detail::column_of<Sp, NH::independents[k]>(x), ev);
    detail::static_for<NH::m>([&](auto r) {
      detail::add_scaled<F>(col, detail::column_of<Sp, NH::dependents[r]>(x),
                            sol.A(Eigen::Index(r), Eigen::Index(k)), ev);
    });
    detail::set_column(out, Eigen::Index(k), col);
  });
  return out;
}

// v~_t = v_t + sum_r v_r B_r, in F.
template <Frame F, class NH, class X, class Ev, class Sol>
auto nonholonomic_remainder(const X& x, const Ev& ev, const Sol& sol) {
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  auto [all, rest] = linear_in_speeds<F>(x, ev);
  for (std::size_t r = 0; r < NH::m; ++r)
    rest += all.col(static_cast<Eigen::Index>(NH::dependents[r] - 1)) * sol.B(static_cast<Eigen::Index>(r));
  return rest;
}

}  // namespace kane
#pragma GCC diagnostic pop
