// Analytical derivatives of inverse and forward dynamics by q and u, from passes over the tree
// (tree/rnea_derivatives.hpp), for a system of joint form whose loads turn with their bodies:
//
//   const auto [tau, dtau_dq, dtau_du, M, status] = kane::inverse_dynamics_derivatives<System>(ev);
//   const auto [ud, dud_dq, dud_du, status] = kane::forward_dynamics_derivatives<System>(ev);
//
// du'/dx = -M^-1 dtau/dx at u', M factored once. Column r is the derivative along the motion of u_r:
// q_c for u_r = q_c'; for a free joint's u_1..6 a rotation vector in its frame's axes, then its
// origin's coordinates.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/invert.hpp"
#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/tree/articulated_solve.hpp"
#include "kane/dynamics/detail/tree/rnea_derivatives.hpp"
#include "kane/dynamics/results.hpp"
#include "kane/evaluation/status.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// Sys takes the analytical derivatives with the evaluator's speeds.
template <class Sys, class Ev>
constexpr bool analytical_derivatives() {
  if constexpr (!tree_form<Sys, Ev> || !(speeds_of<Ev>::identity || free_joint<Sys, Ev>))
    return false;
  else
    return steady_loads_of<Sys, joint_form_of<Sys, Ev>>;
}
template <class JF, class... X, std::size_t... I>
constexpr bool loads_checked(list<X...>, std::index_sequence<I...>) {
  return (check<steady_load<JF, X, I>(), error::analytical_derivatives_need_loads_fixed_in_their_bodies<X>,
                fix::call_kane_linearize> &&
          ...);
}
template <class Sys, class Ev>
constexpr bool derivatives_checked() {
  if constexpr (!tree_form<Sys, Ev> || !(speeds_of<Ev>::identity || free_joint<Sys, Ev>))
    return refused<error::analytical_derivatives_need_a_tree_of_simple_rotations_with_u_equal_to_q_dot<Sys>,
                   fix::call_kane_linearize>;
  else
    return loads_checked<joint_form_of<Sys, Ev>>(
        typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
}
template <class M>
void set_nan(M& m) {
  m.setConstant(std::numeric_limits<typename M::Scalar>::quiet_NaN());
}
// st ok for one state; true for lanes, whose lanes are all computed and the failed ones spoilt.
template <class St>
constexpr bool all_ok_or_lanes(const St& st) {
  if constexpr (std::is_same_v<St, solve_status>)
    return st == solve_status::ok;
  else
    return true;
}
// st = not_finite where a number of the results x is not (lane by lane), then x NaN where st is
// not ok: a branch for one state, products for lanes.
template <class St, class M, class... X>
void finish_results(St& st, M& m, X&... x) {
  using S = typename M::Scalar;
  fail_unless(st, (all_finite_matrix(m) && ... && all_finite_matrix(x)), solve_status::not_finite);
  if constexpr (lane_traits<S>::width == 1) {
    if (st != solve_status::ok) set_nan(m), (set_nan(x), ...);
  } else {
    const auto spoil = nan_unless<S>(ok_of<S>(st));
    spoil(m), (spoil(x), ...);
  }
}
}  // namespace detail

template <System Sys, Evaluator Ev>
requires Numbers<typename Ev::scalar> inverse_derivatives<typename Ev::scalar, Ev::nu>
inverse_dynamics_derivatives(const Ev& ev) {
  static_assert(detail::derivatives_checked<Sys, Ev>());
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  inverse_derivatives<S, n> out;
  if constexpr (detail::analytical_derivatives<Sys, Ev>()) {
    Eigen::Matrix<S, int(n), 1> ud;
    for (std::size_t r = 0; r < n; ++r) ud(Eigen::Index(r)) = detail::joint_rate<2>(ev, r);
    using JF = detail::joint_form_of<Sys, Ev>;
    const detail::body_frames<JF, Ev> bf(ev);
    detail::tree_partials<JF, Sys, Ev> pass(bf, ev);
    pass.outward(ev, ud);
    pass.inward(out.tau, out.M, out.dtau_dq, out.dtau_du);
    out.status = ev.status();
    detail::finish_results(out.status, out.tau, out.dtau_dq, out.dtau_du, out.M);
  }
  return out;
}

namespace detail {
// forward_dynamics_derivatives, and X = -M^-1 X for each extra X (n rows) by the same factor of M.
template <class Sys, class Ev, class... X>
forward_derivatives<typename Ev::scalar, Ev::nu> forward_derivatives_solving(const Ev& ev, X&... extra) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  forward_derivatives<S, n> out;
  // u' first, by a factor of M from composite bodies (Cholesky, for a few speeds or a free joint) or
  // by articulated bodies; then one pass gives dtau/dx at u', and du'/dx = -M^-1 dtau/dx by that factor.
  using JF = joint_form_of<Sys, Ev>;
  const body_frames<JF, Ev> bf(ev);
  tree_partials<JF, Sys, Ev> pass(bf, ev);
  out.status = ev.status();
  const auto factor = [&] {
    if constexpr (n <= articulated_above || free_joint<Sys, Ev> || lane_traits<S>::width > 1) {
      Eigen::Matrix<S, int(n), int(n)> m;
      composite_mass_matrix<JF, Sys>(bf, ev, m);
      fail_unless(out.status, finite_diagonal(m), solve_status::not_finite);
      return cholesky_factor<S, int(n)>(m);
    } else
      return articulated_solve<JF, S>(pass.own, pass.screw);
  }();
  joint_forces<rates::at_rest, JF, Sys>(bf, ev, out.ud);  // -f
  fail_unless(out.status, all_finite_matrix(out.ud), solve_status::not_finite);
  fail_unless(out.status, factor.ok(), solve_status::singular);
  if (all_ok_or_lanes(out.status)) {
    factor.solve_negated(out.ud);
    Eigen::Matrix<S, int(n), int(n)> m;
    Eigen::Matrix<S, int(n), 1> tau;
    pass.outward(ev, out.ud);
    pass.template inward<false>(tau, m, out.dud_dq, out.dud_du);
    factor.solve_negated(out.dud_dq, out.dud_du, extra...);
  }
  finish_results(out.status, out.ud, out.dud_dq, out.dud_du);
  return out;
}
}  // namespace detail

template <System Sys, Evaluator Ev>
requires Numbers<typename Ev::scalar> forward_derivatives<typename Ev::scalar, Ev::nu>
forward_dynamics_derivatives(const Ev& ev) {
  static_assert(detail::derivatives_checked<Sys, Ev>());
  if constexpr (detail::analytical_derivatives<Sys, Ev>())
    return detail::forward_derivatives_solving<Sys>(ev);
  else
    return {};
}

}  // namespace kane
#pragma GCC diagnostic pop
