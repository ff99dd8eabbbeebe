// Holonomic constraints and nonholonomic constraints (eq. 20-22).
//
//   kane::configuration<Particles, RigidBodies, f1, ..., fM>
//       f_k(q, t) = 0; n = 3 Particles + 6 RigidBodies - M at compile time.
//   kane::nonholonomic<Speeds, kane::dependent<4, 5>, c1, c2>
//       c_k linear in the speeds, c_k = 0 (m of them for m dependent speeds);
//       at a state (evaluation/nonholonomic_tables.hpp): u_dep = A u_ind + B, and the
//       nonholonomic partial velocities v~_s = v_s + sum_r v_r A_rs with
//       remainder v~_t = v_t + sum_r v_r B_r.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/structure.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/speeds/kinematic_weights.hpp"
#include "kane/speeds/partial_velocity.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// The configuration constraints f(q, t) = 0 of particles and rigid bodies.
template <std::size_t Particles, std::size_t RigidBodies, auto... F>
struct configuration {
  static_assert((ScalarExpr<decltype(F)> && ...),
                "kane: configuration constraints are scalar expressions f(q, t)");
  // M, the number of constraints
  static constexpr std::size_t constraints = sizeof...(F);
  static_assert(3 * Particles + 6 * RigidBodies >= constraints,
                "kane: more holonomic constraints than coordinates (3 per particle, 6 per rigid body)");
  // Generalized coordinates needed: n = 3v - M with 6 per rigid body (eq. 16).
  static constexpr std::size_t n = 3 * Particles + 6 * RigidBodies - constraints;
  // f_1, ..., f_M
  static constexpr std::tuple<decltype(F)...> equations{F...};
  // d f_k / dt = 0: the velocity constraint of f_k.
  template <std::size_t K>
  static constexpr auto velocity_constraint() {
    return dt(std::get<K>(equations));
  }
};

template <std::size_t... R>
struct dependent {};

template <SpeedSet Sp, class Dependent, auto... C>
struct nonholonomic;

// Nonholonomic constraints C... = 0, linear in the speeds of Sp, solved for the speeds D...
template <SpeedSet Sp, std::size_t... D, auto... C>
struct nonholonomic<Sp, dependent<D...>, C...> {
  // Sp, the speeds constrained
  using speed_set = Sp;
  // the number of speeds
  static constexpr std::size_t n = Sp::n;
  // the number of dependent speeds
  static constexpr std::size_t m = sizeof...(D);
  static_assert(sizeof...(C) == m,
                "kane: m dependent speeds need m constraint equations; the counts in "
                "nonholonomic<Speeds, dependent<...>, c...> differ");
  static_assert(((D >= 1 && D <= n) && ...),
                "kane: the dependent speeds must be speeds of the system (u_1 .. u_n)");
  static_assert(m < n, "kane: at least one speed must stay independent");
  // n - m, the degrees of freedom
  static constexpr std::size_t p = n - m;  // degrees of freedom
  // D..., the r of each dependent u_r
  static constexpr std::array<std::size_t, m> dependents{D...};
  // the r of each independent u_r, ascending
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
  // no dependent speed is named twice
  static constexpr bool distinct_dependents = detail::all_distinct(dependents);
  static_assert(distinct_dependents, "kane: a dependent speed is named twice");
  // C..., the constraint expressions
  static constexpr std::tuple<decltype(C)...> equations{C...};
};

namespace detail {
template <class T>
struct is_nonholonomic : std::false_type {};
template <SpeedSet Sp, std::size_t... D, auto... C>
struct is_nonholonomic<nonholonomic<Sp, dependent<D...>, C...>> : std::true_type {};
}  // namespace detail

// kane::nonholonomic<Speeds, dependent<...>, c...>.
template <class T>
concept Nonholonomic = detail::is_nonholonomic<T>::value;

namespace detail {
// The constraints M u + c0 = 0 as a structured solve (evaluation/block_solve.hpp) of the
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
    return detail::remainder_u<Sp>(std::get<K>(NH::equations), std::make_index_sequence<Sp::rows>{});
  }
  template <std::size_t K, std::size_t J>  // column J of [M_ind | c0]
  static constexpr auto right() {
    if constexpr (J < p)
      return coefficient<K, NH::independents[J]>();
    else
      return rest<K>();
  }
  static constexpr pattern<n, n> m = []<std::size_t... I>(std::index_sequence<I...>) {
    const std::array<entry, n * n> e{entry_of<decltype(coefficient<I / n, NH::dependents[I % n]>())>()...};
    pattern<n, n> out{};
    for (std::size_t i = 0; i < n * n; ++i) out[i / n][i % n] = e[i];
    return out;
  }
  (std::make_index_sequence<n * n>{});
  static constexpr pattern<n, k> r = []<std::size_t... I>(std::index_sequence<I...>) {
    const std::array<entry, n * k> e{entry_of<decltype(right<I / k, I % k>())>()...};
    pattern<n, k> out{};
    for (std::size_t i = 0; i < n * k; ++i) out[i / k][i % k] = e[i];
    return out;
  }
  (std::make_index_sequence<n * k>{});
  static constexpr block_form<n> form = blocks_of(m);
  static constexpr pattern<n, k> x = solution_pattern(m, form, r);
};
// The block of Sys with one right-hand side of numbers only (u_dep' of the differentiated constraints).
template <class Sys>
struct dense_right_side {
  static constexpr std::size_t n = Sys::n, k = 1;
  static constexpr pattern<n, n> m = Sys::m;
  static constexpr block_form<n> form = Sys::form;
  static constexpr pattern<n, 1> r = [] {
    pattern<n, 1> out{};
    for (auto& row : out) row[0] = entry::other;
    return out;
  }();
  static constexpr pattern<n, 1> x = solution_pattern(m, form, r);
};
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
