// Kane's tables of nonholonomic constraints at an evaluator's state: the
// dependent speeds u_dep = A u_ind + B, the nonholonomic partial velocities v~_s = v_s + sum_r v_r A_rs
// and the remainder v~_t = v_t + sum_r v_r B_r.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/evaluation/tables.hpp"
#include "kane/speeds/constraints.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
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
  status_of<S> status;
  // C of C u + c0 = 0: M x (M + P), all speeds
  Eigen::Matrix<S, int(M), int(M + P)> C;
  // c0 of C u + c0 = 0
  Eigen::Matrix<S, int(M), 1> c0;
  // the block of C at the dependent speeds, factored
  detail::factored<S, M> dependent;  // the block of C of the dependent speeds: u_dep' reuses it
};

namespace detail {
// solve_constraints; checking::at_end: A and B neither checked finite nor made NaN (the caller checks
// and spoils its results). rows false: C and c0 left unwritten (for a caller at u' = 0, which reads
// neither). Both are arguments, folded where the call inlines: one instantiation serves every caller.
template <class NH, class Ev>
KANE_ALWAYS_INLINE auto solve_constraints_as(const Ev& ev, checking check, bool rows) {
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
  if (rows) {
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
  }
  out.dependent.m = dep;
  out.dependent.factors = detail::factor_structured<Sys>(dep);
  const auto solved = detail::substitute_structured_as<Sys, known_entries::written>(
      dep, out.dependent.factors, right, x, check);
  out.status = detail::failed_first(ev.status(), solved);
  for (std::size_t k = 0; k < m; ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    for (std::size_t j = 0; j < p; ++j) out.A(row, static_cast<Eigen::Index>(j)) = -x[k][j];
    out.B(row) = -x[k][p];
  }
  if (check == checking::each) {  // at_end: the caller's results are NaN unless ok
    const auto spoil = detail::nan_unless<S>(detail::ok_of<S>(out.status));
    spoil(out.A);
    spoil(out.B);
  }
  return out;
}
template <class NH, checking Check, bool Rows = true, class Ev>
KANE_ALWAYS_INLINE auto solve_constraints_at(const Ev& ev) {
  return solve_constraints_as<NH>(ev, Check, Rows);
}
}  // namespace detail

// u_dep = A u_ind + B at the evaluator's state.
template <Nonholonomic NH, Evaluator Ev>
KANE_INLINE_FLATTEN auto solve_constraints(const Ev& ev) {
  return detail::solve_constraints_at<NH, detail::checking::each>(ev);
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
template <Frame F, Nonholonomic NH, class X, Evaluator Ev, class Sol>
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
template <Frame F, Nonholonomic NH, class X, Evaluator Ev, class Sol>
auto nonholonomic_remainder(const X& x, const Ev& ev, const Sol& sol) {
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  auto [all, rest] = linear_in_speeds<F>(x, ev);
  for (std::size_t r = 0; r < NH::m; ++r)
    rest += all.col(static_cast<Eigen::Index>(NH::dependents[r] - 1)) * sol.B(static_cast<Eigen::Index>(r));
  return rest;
}

}  // namespace kane
#pragma GCC diagnostic pop
