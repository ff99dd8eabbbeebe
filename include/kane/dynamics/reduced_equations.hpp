// Kane's equations of a nonholonomic system for its p independent
// speeds, summed along the nonholonomic partial velocities v~ = v T
// (Kane's sums, sums.hpp, with the columns of T): no n x n M is formed. Also the n
// equations with their constraint rows, and F~, F~* along v~.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/generalized_forces.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/evaluation/nonholonomic_tables.hpp"
#include "kane/evaluation/status.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The independent speeds of the constraints NH along v~ = v T:
// v~_k = v_ind_k + sum_j v_dep_j A_jk, and v b = sum_j v_dep_j b_j adds to the
// bias acceleration (u' = T u_ind' + b).
template <class NH, class S>
struct independent_speeds {
  static constexpr std::size_t n = NH::p;
  const Eigen::Matrix<S, int(NH::m), int(NH::p)>& A;
  const std::array<S, NH::m>& b;
  template <auto Nz>
  static constexpr std::array<bool, n> nonzero() {
    bool dependent = false;
    for (std::size_t j = 0; j < NH::m; ++j) dependent = dependent || !all_zero(Nz[NH::dependents[j] - 1]);
    std::array<bool, n> out{};
    for (std::size_t k = 0; k < n; ++k) out[k] = !all_zero(Nz[NH::independents[k] - 1]) || dependent;
    return out;
  }
  template <auto Nz>
  static constexpr std::array<pattern3, n> kinds() {  // v~_k is v_ind_k where no dependent column enters
    bool dependent = false;
    for (std::size_t j = 0; j < NH::m; ++j) dependent = dependent || !all_zero(Nz[NH::dependents[j] - 1]);
    std::array<pattern3, n> out{};
    for (std::size_t k = 0; k < n; ++k) out[k] = dependent ? unknown3 : Nz[NH::independents[k] - 1];
    return out;
  }
  // How v_dep_j enters row r of v~_k: 0 not, 1 as v_rj A_jk, 2 as + A_jk (v_dep_j = e_r), 3 as - A_jk
  template <auto Nz>
  static constexpr std::array<std::array<int, NH::m>, 3> dependent_terms() {
    std::array<std::array<int, NH::m>, 3> out{};
    for (std::size_t j = 0; j < NH::m; ++j) {
      const pattern3 kind = Nz[NH::dependents[j] - 1];
      const int i = column_axis(kind);
      for (std::size_t r = 0; r < 3; ++r)
        out[r][j] = all_zero(kind) || (i >= 0 && std::size_t(i) != r) ? 0
                    : i < 0                                           ? 1
                    : kind[std::size_t(i)] == entry::one              ? 2
                                                                      : 3;
    }
    return out;
  }
  // v~_rk, the dependent terms in a fold (no function a term)
  template <auto Nz, std::size_t r, std::size_t k, class V, std::size_t... j>
  KANE_ALWAYS_INLINE S column_entry(const V& v, std::index_sequence<j...>) const {
    constexpr auto t = dependent_terms<Nz>()[r];
    S x = S(0);
    if constexpr (!all_zero(Nz[NH::independents[k] - 1]))
      x = v(Eigen::Index(r), Eigen::Index(NH::independents[k] - 1));
    (void(t[j] == 1 ? x += v(Eigen::Index(r), Eigen::Index(NH::dependents[j] - 1)) *
                           A(Eigen::Index(j), Eigen::Index(k))
          : t[j] == 2 ? x += A(Eigen::Index(j), Eigen::Index(k))
          : t[j] == 3 ? x -= A(Eigen::Index(j), Eigen::Index(k))
                      : x),
     ...);
    return x;
  }
  template <auto Nz, class V>
  KANE_ALWAYS_INLINE Eigen::Matrix<S, 3, int(n)> columns(const V& v) const {
    Eigen::Matrix<S, 3, int(n)> t;
    store_in_blocks<3 * n>(t.data(), [&](auto rk) KANE_ALWAYS_INLINE_LAMBDA {  // row r of column k
      return column_entry<Nz, rk % 3, rk / 3>(v, std::make_index_sequence<NH::m>{});
    });
    return t;
  }
  template <auto Nz, class X, class V>
  KANE_ALWAYS_INLINE void add_bias(X& a0, const V& v) const {
    static_for<NH::m>([&](auto j) {
      constexpr pattern3 kind = Nz[NH::dependents[j] - 1];
      constexpr int i = column_axis(kind);
      if constexpr (all_zero(kind))
        return;
      else if constexpr (i < 0)
        a0 += v.col(Eigen::Index(NH::dependents[j] - 1)) * b[j];
      else if constexpr (kind[std::size_t(i)] == entry::one)
        a0(i) += b[j];
      else
        a0(i) -= b[j];
    });
  }
};
}  // namespace detail

// Kane's equations of a nonholonomic system for its p independent
// speeds: with u_dep = A u_ind + B (sol, of the constraints NH at ev's state),
// u' = T u_ind' + b, T = [1; A] (rows in speed order) and b = u_dep' at u_ind' = 0
// from the differentiated constraints, C u' + (C' u + c0') = 0; then
// M~ = T^T M T and f~ = T^T (f - M b): the equations along the nonholonomic partial
// velocities v~_r (the constraint forces do no work there). u_dep' = A u_ind' + b_dep.
template <class S, std::size_t N, std::size_t P>
struct reduced_equations {
  // M~ u_ind' = f~, with its status
  equations_of_motion<S, P> reduced;   // M~ u_ind' = f~
  Eigen::Matrix<S, int(N), int(P)> T;  // u' = T u_ind' + b
  // u' at u_ind' = 0: b_dep at the dependent speeds, else 0
  Eigen::Matrix<S, int(N), 1> b;
};
namespace detail {
// T of u' = T u_ind' + b: ones at the independent speeds, the rows of A at the dependent ones.
template <class NH, class S>
Eigen::Matrix<S, int(NH::n), int(NH::p)> speeds_of_independents(
    const Eigen::Matrix<S, int(NH::m), int(NH::p)>& a) {
  Eigen::Matrix<S, int(NH::n), int(NH::p)> t = Eigen::Matrix<S, int(NH::n), int(NH::p)>::Zero();
  for (std::size_t k = 0; k < NH::p; ++k) t(Eigen::Index(NH::independents[k] - 1), Eigen::Index(k)) = S(1);
  for (std::size_t j = 0; j < NH::m; ++j) t.row(Eigen::Index(NH::dependents[j] - 1)) = a.row(Eigen::Index(j));
  return t;
}
// dt(c) of the constraints at the evaluator's state and u': one instantiation for every rates.
template <class NH, class Ev>
Eigen::Matrix<typename Ev::scalar, int(NH::m), 1> constraint_rates(const Ev& ev) {
  using S = typename Ev::scalar;
  constexpr std::size_t m = NH::m;
  Eigen::Matrix<S, int(m), 1> rest;
  [&]<std::size_t... K>(std::index_sequence<K...>) {
    with_common_subexpressions<decltype(dt(std::get<K>(NH::equations)))...>(ev, [&](const auto& e) {
      detail::static_for<m>([&](auto k) {
        constexpr auto dc = dt(std::get<k>(NH::equations));
        rest(Eigen::Index(k)) = detail::eval_scalar(dc, e);
      });
    });
  }
  (std::make_index_sequence<m>{});
  return rest;
}
// C' u + c0' = dt(c) - C u' of the constraints (rates::at_rest: the evaluator's u' are zero).
template <class NH, rates Rates, class Ev, class Sol>
Eigen::Matrix<typename Ev::scalar, int(NH::m), 1> constraint_rates_at_rest(const Ev& ev, const Sol& sol) {
  Eigen::Matrix<typename Ev::scalar, int(NH::m), 1> rest = constraint_rates<NH>(ev);
  if constexpr (Rates == rates::of_state) rest -= sol.C * detail::speed_rates(ev);
  return rest;
}
// b_dep of u_dep' = A u_ind' + b_dep: -C_dep^-1 (C' u + c0'), with the factors of C_dep that
// solve_constraints found.
template <class NH, rates Rates, checking Check = checking::each, class Ev, class Sol>
status_of<typename Ev::scalar> dependent_rates_at_rest(const Ev& ev, const Sol& sol,
                                                       std::array<typename Ev::scalar, NH::m>& b_dep) {
  using S = typename Ev::scalar;
  constexpr std::size_t m = NH::m;
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  const Eigen::Matrix<S, int(m), 1> rest = constraint_rates_at_rest<NH, Rates>(ev, sol);
  using Dep = detail::dense_right_side<detail::constraint_system<NH>>;
  detail::table<S, m, 1> right, bd;
  for (std::size_t k = 0; k < m; ++k) right[k][0] = rest(Eigen::Index(k));
  const auto solved = detail::substitute_structured<Dep, known_entries::written, Check>(
      sol.dependent.m, sol.dependent.factors, right, bd);
  for (std::size_t j = 0; j < m; ++j) b_dep[j] = -bd[j][0];
  return solved;
}
// M~ u_ind' = f~ alone (Check: checking::at_end for a caller that checks u_ind' and q'), b_dep into b_dep.
template <class Sys, class NH, rates Rates, checking Check = checking::each, class Ev, class Sol>
equations_of_motion<typename Ev::scalar, NH::p> reduced_equations_at(
    const Ev& ev, const Sol& sol, std::array<typename Ev::scalar, NH::m>& b_dep) {
  using S = typename Ev::scalar;
  const auto solved = dependent_rates_at_rest<NH, Rates, Check>(ev, sol, b_dep);
  auto out = equations_along<Sys, Rates, parts::both, Check>(ev, independent_speeds<NH, S>{sol.A, b_dep});
  out.status = failed_first(sol.status, out.status);  // a failed solve first: it made u_dep NaN
  detail::then(out.status, solved);
  return out;
}
template <class Sys, class NH, rates Rates, class Ev, class Sol>
reduced_equations<typename Ev::scalar, NH::n, NH::p> reduced_mass_matrix_and_forcing_at(const Ev& ev,
                                                                                        const Sol& sol) {
  using S = typename Ev::scalar;
  std::array<S, NH::m> b_dep;
  // built in place: a copy of the equations would read whole what was written number by number
  reduced_equations<S, NH::n, NH::p> out{reduced_equations_at<Sys, NH, Rates>(ev, sol, b_dep),
                                         speeds_of_independents<NH>(sol.A),
                                         Eigen::Matrix<S, int(NH::n), 1>::Zero()};
  for (std::size_t j = 0; j < NH::m; ++j) out.b(Eigen::Index(NH::dependents[j] - 1)) = b_dep[j];
  return out;
}
}  // namespace detail
// M~, f~, T and b of Sys at ev's state, with sol the solution of the constraints NH
template <System Sys, Nonholonomic NH, Evaluator Ev, class Sol>
reduced_equations<typename Ev::scalar, NH::n, NH::p> reduced_mass_matrix_and_forcing(const Ev& ev,
                                                                                     const Sol& sol) {
  if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>())
    return {};
  else
    return detail::flat<typename Ev::scalar>([&] {
      return detail::reduced_mass_matrix_and_forcing_at<Sys, NH, detail::rates::of_state>(ev, sol);
    });
}

// The n equations of a nonholonomic system with its constraint rows, M u' = f in speed order (SymPy's
// KanesMethod.mass_matrix and forcing): the row of an independent speed u_r is Kane's equation along
// v~_r, (T^T M)_r u' = (T^T f)_r, with M, f the equations of all n speeds (mass_matrix_and_forcing.hpp); the
// row of the j-th dependent speed is the j-th constraint differentiated, C_j u' = -(C' u + c0')_j, with C the
// constraints' Jacobian by u as written. status: the equations' or the solution's.
template <System Sys, Nonholonomic NH, Evaluator Ev, class Sol>
equations_of_motion<typename Ev::scalar, NH::n> constrained_mass_matrix_and_forcing(const Ev& ev,
                                                                                    const Sol& sol) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = NH::n, p = NH::p;
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>()) {
    return {};
  } else {
    const auto e = mass_matrix_and_forcing<Sys>(ev);
    const Eigen::Matrix<S, int(n), int(p)> t = detail::speeds_of_independents<NH>(sol.A);
    const Eigen::Matrix<S, int(NH::m), 1> rest =
        detail::constraint_rates_at_rest<NH, detail::rates::of_state>(ev, sol);
    equations_of_motion<S, n> out{Eigen::Matrix<S, int(n), int(n)>::Zero(), Eigen::Matrix<S, int(n), 1>(),
                                  e.status};
    for (std::size_t k = 0; k < p; ++k) {
      const auto r = Eigen::Index(NH::independents[k] - 1);
      out.M.row(r) = t.col(Eigen::Index(k)).transpose() * e.M;
      out.f(r) = t.col(Eigen::Index(k)).dot(e.f);
    }
    for (std::size_t j = 0; j < NH::m; ++j) {
      const auto r = Eigen::Index(NH::dependents[j] - 1);
      out.M.row(r) = sol.C.row(Eigen::Index(j));
      out.f(r) = -rest(Eigen::Index(j));
    }
    detail::then(out.status, sol.status);
    detail::fail_unless(out.status, detail::all_finite_matrix(out.M) && detail::all_finite_matrix(out.f),
                        solve_status::not_finite);
    return out;
  }
}

// Kane's generalized forces along the nonholonomic partial velocities, F~ = T^T F and
// F~* = T^T F*, at the evaluator's state (F* at its u'; F~ + F~* = 0 is the reduced equations).
// F from generalized_active_force (one expression per speed), F* = f - F - M u' from the full
// equations. status: the evaluator's, the solution's, or not_finite.
template <class S, std::size_t P>
struct reduced_forces {
  // F~ = T^T F
  Eigen::Matrix<S, int(P), 1> active;   // F~_r
  Eigen::Matrix<S, int(P), 1> inertia;  // F~*_r
  // the evaluator's, the solution's, or not_finite
  status_of<S> status;
};
// F~ and F~* of Sys at ev's state, with sol the solution of the constraints NH
template <System Sys, Nonholonomic NH, Evaluator Ev, class Sol>
reduced_forces<typename Ev::scalar, NH::p> reduced_generalized_forces(const Ev& ev, const Sol& sol) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = NH::n, p = NH::p;
  static_assert(detail::same_speeds_v<Ev, NH> && detail::solution_of_v<Sol, NH>);
  if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>()) {
    return {};
  } else {
    Eigen::Matrix<S, int(n), 1> active;
    detail::static_for<n>([&](auto r) {
      active(Eigen::Index(r)) =
          evaluate(generalized_active_force<typename Ev::root, Sys, typename NH::speed_set, r + 1>(), ev);
    });
    const auto e = mass_matrix_and_forcing<Sys>(ev);
    const Eigen::Matrix<S, int(n), 1> inertia = e.f - active - e.M * detail::speed_rates(ev);
    const Eigen::Matrix<S, int(n), int(p)> t = detail::speeds_of_independents<NH>(sol.A);
    reduced_forces<S, p> out{t.transpose() * active, t.transpose() * inertia, e.status};
    detail::then(out.status, sol.status);
    detail::fail_unless(out.status,
                        detail::all_finite_matrix(out.active) && detail::all_finite_matrix(out.inertia),
                        solve_status::not_finite);
    return out;
  }
}

}  // namespace kane
#pragma GCC diagnostic pop
