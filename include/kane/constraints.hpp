// Holonomic constraints (seed eq. 16) and nonholonomic constraints (eq. 20-22).
//
//   kane::configuration<Particles, RigidBodies, f1, ..., fM>
//       f_k(q, t) = 0; n = 3 Particles + 6 RigidBodies - M at compile time.
//   kane::nonholonomic<Speeds, kane::dependent<4, 5>, c1, c2>
//       c_k linear in the speeds, c_k = 0 (m of them for m dependent speeds);
//       at a state: u_dep = A u_ind + B, and the nonholonomic partial
//       velocities v~_s = v_s + sum_r v_r A_rs with remainder v~_t = v_t + sum_r v_r B_r.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <tuple>
#include <utility>

#include <Eigen/Core>

#include "kane/derivative.hpp"
#include "kane/evaluator.hpp"
#include "kane/partial_velocity.hpp"
#include "kane/speeds.hpp"

namespace kane {

template <std::size_t Particles, std::size_t RigidBodies, auto... F>
struct configuration {
  static_assert((ScalarExpr<decltype(F)> && ...),
                "kane: configuration constraints are scalar expressions f(q, t)");
  static constexpr std::size_t constraints = sizeof...(F);
  static_assert(3 * Particles + 6 * RigidBodies >= constraints,
                "kane: more holonomic constraints than coordinates (3 per particle, 6 per rigid body)");
  // Generalized coordinates needed: n = 3v - M with 6 per rigid body (eq. 16).
  static constexpr std::size_t n = 3 * Particles + 6 * RigidBodies - constraints;
  static constexpr std::tuple<decltype(F)...> equations{F...};
  // d f_k / dt = 0: the velocity constraint of f_k.
  template <std::size_t K>
  static constexpr auto velocity_constraint() {
    return dt(std::get<K>(equations));
  }
};

// f_k at the evaluator's state, and their time derivatives.
template <class Config, class Ev>
auto residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(std::get<K>(Config::equations), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}
template <class Config, class Ev>
auto velocity_residuals(const Ev& ev) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<typename Ev::scalar, Config::constraints>{
        evaluate(Config::template velocity_constraint<K>(), ev)...};
  }
  (std::make_index_sequence<Config::constraints>{});
}

template <std::size_t... R>
struct dependent {};

template <SpeedSet Sp, class Dependent, auto... C>
struct nonholonomic;

template <SpeedSet Sp, std::size_t... D, auto... C>
struct nonholonomic<Sp, dependent<D...>, C...> {
  using speed_set = Sp;
  static constexpr std::size_t n = Sp::n;
  static constexpr std::size_t m = sizeof...(D);
  static_assert(sizeof...(C) == m,
                "kane: m dependent speeds need m constraint equations; the counts in "
                "nonholonomic<Speeds, dependent<...>, c...> differ");
  static_assert(((D >= 1 && D <= n) && ...),
                "kane: the dependent speeds must be speeds of the system (u_1 .. u_n)");
  static_assert(m < n, "kane: at least one speed must stay independent");
  static constexpr std::size_t p = n - m;  // degrees of freedom
  static constexpr std::array<std::size_t, m> dependents{D...};
  static constexpr std::array<std::size_t, p> independents = [] {
    std::array<std::size_t, p> r{};
    std::size_t k = 0;
    for (std::size_t i = 1; i <= n; ++i) {
      bool dep = false;
      for (std::size_t j : dependents) dep = dep || j == i;
      if (!dep && k < p) r[k++] = i;
    }
    return r;
  }();
  static_assert(
      [] {
        for (std::size_t i = 0; i < m; ++i)
          for (std::size_t j = 0; j < i; ++j)
            if (dependents[i] == dependents[j]) return false;
        return true;
      }(),
      "kane: a dependent speed is named twice");
  static constexpr std::tuple<decltype(C)...> equations{C...};
};

// u_dep = A u_ind + B at a state; status says whether the dependent block was
// solvable (A and B are NaN when it is singular or not finite).
template <class S, std::size_t M, std::size_t P>
struct constraint_solution {
  Eigen::Matrix<S, int(M), int(P)> A;
  Eigen::Matrix<S, int(M), 1> B;
  solve_status status;
};

template <class NH, class Ev>
auto solve_constraints(const Ev& ev) {
  using S = typename Ev::scalar;
  static_assert(std::is_same_v<typename NH::speed_set, detail::speeds_of<Ev>>,
                "kane: the constraints and the evaluator use different speed sets");
  constexpr std::size_t n = NH::n, m = NH::m, p = NH::p;
  // c = M u + c0 = 0
  Eigen::Matrix<S, int(m), int(n)> coeff;
  Eigen::Matrix<S, int(m), 1> c0;
  [&]<std::size_t... K>(std::index_sequence<K...>) {
    (
        [&] {
          const auto [row, rest] = linear_in_speeds<root_frame>(std::get<K>(NH::equations), ev);
          coeff.row(K) = row;
          c0(K) = rest(0);
        }(),
        ...);
  }
  (std::make_index_sequence<m>{});
  Eigen::Matrix<S, int(m), int(m)> dep;
  Eigen::Matrix<S, int(m), int(p)> ind;
  for (std::size_t k = 0; k < m; ++k) dep.col(k) = coeff.col(NH::dependents[k] - 1);
  for (std::size_t k = 0; k < p; ++k) ind.col(k) = coeff.col(NH::independents[k] - 1);
  constraint_solution<S, m, p> out;
  Eigen::Matrix<S, int(m), int(m)> inv;
  out.status = !(coeff.allFinite() && c0.allFinite()) ? solve_status::not_finite
               : !detail::invert(dep, inv)            ? solve_status::singular
                                                      : solve_status::ok;
  if (out.status == solve_status::ok) {
    out.A = -inv * ind;
    out.B = -inv * c0;
  } else {
    out.A.setConstant(std::numeric_limits<S>::quiet_NaN());
    out.B.setConstant(std::numeric_limits<S>::quiet_NaN());
  }
  return out;
}

// [v~_1 ... v~_p] in F: v~_s = v_s + sum_r v_r A_rs over the independent s.
template <Frame F, class NH, class X, class Ev, class Sol>
auto nonholonomic_partial_velocities(const X& x, const Ev& ev, const Sol& sol) {
  const auto all = partial_velocities<F>(x, ev);
  using S = typename Ev::scalar;
  Eigen::Matrix<S, decltype(all)::RowsAtCompileTime, int(NH::p)> out;
  for (std::size_t k = 0; k < NH::p; ++k) out.col(k) = all.col(NH::independents[k] - 1);
  for (std::size_t r = 0; r < NH::m; ++r) out += all.col(NH::dependents[r] - 1) * sol.A.row(r);
  return out;
}

// v~_t = v_t + sum_r v_r B_r, in F.
template <Frame F, class NH, class X, class Ev, class Sol>
auto nonholonomic_remainder(const X& x, const Ev& ev, const Sol& sol) {
  auto [all, rest] = linear_in_speeds<F>(x, ev);
  for (std::size_t r = 0; r < NH::m; ++r) rest += all.col(NH::dependents[r] - 1) * sol.B(r);
  return rest;
}

}  // namespace kane
