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
#include "kane/detail/solve.hpp"
#include "kane/detail/structure.hpp"
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

namespace detail {
// The constraints M u + c0 = 0 as a structured solve (detail/solve.hpp) of the
// dependent block for [A | B] = -M_dep^-1 [M_ind | c0].
template <class NH>
struct constraint_system {
  using Sp = typename NH::speed_set;
  static constexpr std::size_t n = NH::m, p = NH::p, k = p + 1;
  template <std::size_t K, std::size_t R>  // the coefficient of u_R in c_K
  static constexpr auto coefficient() {
    return partial_velocity<Sp>(std::get<K>(NH::equations), speed<R>{});
  }
  template <std::size_t K>
  static constexpr auto rest() {
    return velocity_remainder<Sp>(std::get<K>(NH::equations));
  }
  template <std::size_t K, std::size_t J>  // column J of [M_ind | c0]
  static constexpr auto right() {
    if constexpr (J < p)
      return coefficient<K, NH::independents[J]>();
    else
      return rest<K>();
  }
  static constexpr pattern<n, n> m = []<std::size_t... I>(std::index_sequence<I...>) {
    pattern<n, n> out{};
    ((out[I / n][I % n] = entry_of<decltype(coefficient<I / n, NH::dependents[I % n]>())>()), ...);
    return out;
  }
  (std::make_index_sequence<n * n>{});
  static constexpr pattern<n, k> r = []<std::size_t... I>(std::index_sequence<I...>) {
    pattern<n, k> out{};
    ((out[I / k][I % k] = entry_of<decltype(right<I / k, I % k>())>()), ...);
    return out;
  }
  (std::make_index_sequence<n * k>{});
  static constexpr block_form<n> form = blocks_of(m);
  static constexpr pattern<n, k> x = solution_pattern(m, form, r);
};
}  // namespace detail

// u_dep = A u_ind + B at the evaluator's state.
template <class NH, class Ev>
KANE_FLATTEN auto solve_constraints(const Ev& ev) {
  using S = typename Ev::scalar;
  using Sys = detail::constraint_system<NH>;
  static_assert(std::is_same_v<typename NH::speed_set, detail::speeds_of<Ev>>,
                "kane: the constraints and the evaluator use different speed sets");
  static_assert(Sys::form.regular,
                "kane: the constraints do not determine the dependent speeds (their block of coefficients is "
                "singular at every state); choose dependent speeds that the constraints involve");
  constexpr std::size_t m = NH::m, p = NH::p;
  detail::table<S, m, m> dep;
  detail::table<S, m, p + 1> right, x;
  detail::static_for<m * m>([&](auto kj) {
    constexpr std::size_t k = kj / m, j = kj % m;
    if constexpr (Sys::m[k][j] == detail::entry::other)
      dep[k][j] = detail::eval_scalar(Sys::template coefficient<k, NH::dependents[j]>(), ev);
  });
  detail::static_for<m*(p + 1)>([&](auto kj) {
    constexpr std::size_t k = kj / (p + 1), j = kj % (p + 1);
    if constexpr (Sys::r[k][j] == detail::entry::other)
      right[k][j] = detail::eval_scalar(Sys::template right<k, j>(), ev);
  });
  constraint_solution<S, m, p> out;
  out.status = detail::solve_structured<Sys>(dep, right, x);
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t j = 0; j < p; ++j) out.A(k, j) = -x[k][j];
    out.B(k) = -x[k][p];
  }
  if (out.status != solve_status::ok) {
    out.A.setConstant(std::numeric_limits<S>::quiet_NaN());
    out.B.setConstant(std::numeric_limits<S>::quiet_NaN());
  }
  return out;
}

namespace detail {
// col += a v in F; a v_r that is +-e_Fi adds to one component.
template <class F, class V, class Col, class S, class Ev>
void add_scaled(Col& col, const V& v, S a, const Ev& ev) {
  if constexpr (is_zero_v<V> || is_zero_vector_v<V>)
    return;
  else if constexpr (is_unit<V>::value && std::is_same_v<typename V::frame, F>)
    col(V::index - 1) += a;
  else if constexpr (is_vneg<V>::value && is_unit<decltype(v.v)>::value &&
                     std::is_same_v<typename decltype(v.v)::frame, F>)
    col(decltype(v.v)::index - 1) -= a;
  else
    col += numbers<F>(v, ev) * a;
}
}  // namespace detail

// [v~_1 ... v~_p] in F: v~_s = v_s + sum_r v_r A_rs over the independent s.
template <Frame F, class NH, class X, class Ev, class Sol>
KANE_FLATTEN auto nonholonomic_partial_velocities(const X& x, const Ev& ev, const Sol& sol) {
  using S = typename Ev::scalar;
  using Sp = typename NH::speed_set;
  static_assert(std::is_same_v<Sp, detail::speeds_of<Ev>>,
                "kane: the constraints and the evaluator use different speed sets");
  Eigen::Matrix<S, ScalarExpr<X> ? 1 : 3, int(NH::p)> out;
  detail::static_for<NH::p>([&](auto k) {
    auto col = detail::numbers<F>(detail::column<Sp, NH::independents[k]>(x), ev);
    detail::static_for<NH::m>([&](auto r) {
      detail::add_scaled<F>(col, detail::column<Sp, NH::dependents[r]>(x),
                            sol.A(Eigen::Index(r), Eigen::Index(k)), ev);
    });
    out.col(k) = col;
  });
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
