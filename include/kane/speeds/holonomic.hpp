// Holonomic constraints f_k(q, t) = 0 with named dependent coordinates:
//
//   using loop = kane::holonomic<kane::dependent_coordinates<2, 3>, f1, f2>;
//
// M = sizeof...(f) equations for M dependent coordinates; the Jacobian
// J_kd = df_k/dq_d over the dependent q_d is derived here, and its zero
// pattern must admit a regular matrix (every dependent coordinate in some
// equation). n = NQ - M coordinates stay free (degrees_of_freedom). Solving
// for the dependent q is evaluation/configuration.hpp; the velocity
// constraints df_k/dt = 0 are nonholonomic constraints in the form of eq. 20,
// velocity_constraints<Speeds, dependent<...>>.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <utility>

#include "kane/detail/structure.hpp"
#include "kane/frames/state.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/speeds/constraints.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

template <std::size_t... I>
struct dependent_coordinates {};

template <class Dependent, auto... F>
struct holonomic;

// Holonomic constraints F...(q, t) = 0 solved for the coordinates D...
template <std::size_t... D, auto... F>
struct holonomic<dependent_coordinates<D...>, F...> {
  static_assert((ScalarExpr<decltype(F)> && ...),
                "kane: holonomic constraints are scalar expressions f(q, t)");
  // the number of constraints and of dependent coordinates
  static constexpr std::size_t m = sizeof...(F);
  static_assert(sizeof...(D) == m,
                "kane: m dependent coordinates need m holonomic constraints; the counts in "
                "holonomic<dependent_coordinates<...>, f...> differ");
  static_assert(((D >= 1) && ...), "kane: generalized coordinates are numbered from 1 (q1, q2, ...)");
  // D..., the i of each dependent q_i
  static constexpr std::array<std::size_t, m> dependents{D...};
  // no dependent coordinate is named twice
  static constexpr bool distinct_dependents = detail::all_distinct(dependents);
  static_assert(distinct_dependents, "kane: a dependent coordinate is named twice");
  // the largest i of a dependent q_i
  static constexpr std::size_t last_dependent = [] {
    std::size_t r = 0;
    for (std::size_t d : dependents) r = d > r ? d : r;
    return r;
  }();
  // F..., the constraint expressions
  static constexpr std::tuple<decltype(F)...> equations{F...};

  // J_kd = df_k/dq_d over the dependent coordinates, and the structured solve of J dq = f.
  template <std::size_t K, std::size_t J>
  static constexpr auto jacobian() {
    return diff(std::get<K>(equations), coordinate<dependents[J]>{});
  }
  // the pattern of J: zero, one or other entries
  static constexpr detail::pattern<m, m> m_pattern = []<std::size_t... I>(std::index_sequence<I...>) {
    const std::array<detail::entry, m * m> e{detail::entry_of<decltype(jacobian<I / m, I % m>())>()...};
    detail::pattern<m, m> out{};
    for (std::size_t i = 0; i < m * m; ++i) out[i / m][i % m] = e[i];
    return out;
  }
  (std::make_index_sequence<m * m>{});
  // the blocks of the structured solve of J dq = f
  static constexpr detail::block_form<m> form = detail::blocks_of(m_pattern);
  static_assert(form.regular,
                "kane: the holonomic constraints do not determine the dependent coordinates (their Jacobian "
                "is singular at every configuration); name coordinates that the constraints involve");

  // df_k/dt = 0 as nonholonomic constraints of the speeds Sp, solved for the dependent speeds R...
  // (for qdot_speeds, the rates of the dependent coordinates).
  template <SpeedSet Sp, class R = dependent<D...>>
  using velocity_constraints = nonholonomic<Sp, R, dt(F)...>;
};

namespace detail {
template <class H>
struct is_holonomic : std::false_type {};
template <std::size_t... D, auto... F>
struct is_holonomic<holonomic<dependent_coordinates<D...>, F...>> : std::true_type {};

// The structured solve J dq = f (block_solve.hpp): m = J's pattern, r = f, x = dq.
template <class H>
struct newton_system {
  static constexpr std::size_t n = H::m, k = 1;
  static constexpr pattern<n, n> m = H::m_pattern;
  static constexpr pattern<n, k> r = [] {
    pattern<n, k> out{};
    for (auto& row : out) row[0] = entry::other;
    return out;
  }();
  static constexpr block_form<n> form = H::form;
  static constexpr pattern<n, k> x = solution_pattern(m, form, r);
};
}  // namespace detail

template <class H>
concept Holonomic = detail::is_holonomic<H>::value;

// n = NQ - M: the coordinates of the state St that the constraints H leave free.
template <State St, Holonomic H>
inline constexpr std::size_t degrees_of_freedom = St::nq - H::m;

}  // namespace kane
#pragma GCC diagnostic pop
