// Entry points of the dynamics at the evaluator's state, each with the status of
// the evaluator (or not_finite, or singular):
//
//   kane::inverse_dynamics<Sys>(ev)  tau = M u' - f: the generalized forces that,
//                                    added to the system's loads, give the state's u'
//   kane::forcing<Sys>(ev)           f alone (tau at u' = 0 is -f, the bias)
//   kane::forward_dynamics<Sys>(ev)  u' = M^-1 f
//
// For a system of joint form (joint_form.hpp) tau and f come from one outward and
// one inward pass (rnea.hpp) and M from composite bodies (crba.hpp); otherwise
// from Kane's sums (equations.hpp). Each returns a named result (results.hpp): {tau,
// status}, {f, status}, {ud, status}; when the status is not ok the numbers are NaN.
#pragma once

#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/dynamics/aba.hpp"
#include "kane/dynamics/equations.hpp"
#include "kane/dynamics/system_rules.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// tau at the state's u' (Rest false) or at u' = 0 (Rest true); -tau with Negated; as Out.
template <class Sys, bool Rest, bool Negated, class Out, class Ev>
Out inverse_at(const Ev& ev) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  Eigen::Matrix<S, int(n), 1> tau;
  if constexpr (recursive_form<Sys, Ev>) {
    static_assert(system_checked<Sys, speeds_of<Ev>>(typename Sys::items{}));
    using JF = joint_form_of<Sys, Ev>;
    const body_frames<JF, Ev> bf(ev);
    joint_forces<Rest, JF, Sys, Negated>(bf, ev, tau);
  } else {
    const auto e = mass_matrix_and_forcing_at<Sys, false>(ev);
    if constexpr (Rest && Negated)
      tau = e.f;
    else if constexpr (Rest)
      tau = -e.f;
    else
      tau = e.M * speed_rates(ev) - e.f;
  }
  solve_status status = ev.status();
  if (status == solve_status::ok && !all_finite_matrix(tau)) status = solve_status::not_finite;
  if (status != solve_status::ok) tau.setConstant(std::numeric_limits<S>::quiet_NaN());
  return {tau, status};
}

// Above this many speeds u' of numbers comes from articulated bodies (aba.hpp), below (and for
// jets) from M and a Cholesky factorization: the crossing of the two on a spatial chain with full
// inertias (benchmarks/chain_dynamics; the performance page gives the figures).
inline constexpr std::size_t articulated_above = 20;
// M of Kane's sums is a table of numbers (known_mass_matrix.hpp)
template <class Sys, class Ev>
constexpr bool known_masses() {
  if constexpr (!admitted<Sys, speeds_of<Ev>>() || recursive_form<Sys, Ev>)
    return false;
  else
    return known_mass_matrix<Sys, typename Ev::root, speeds_of<Ev>>.known;
}
// u' = M^-1 f; RestRates: the state's u' is 0 (as in motion.hpp).
template <class Sys, bool RestRates, class Ev>
forward_result<typename Ev::scalar, Ev::nu> forward_at(const Ev& ev) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  if constexpr (recursive_form<Sys, Ev> && (n > articulated_above) && std::is_floating_point_v<S>) {
    static_assert(system_checked<Sys, speeds_of<Ev>>(typename Sys::items{}));
    using JF = joint_form_of<Sys, Ev>;
    Eigen::Matrix<S, int(n), 1> ud;
    const body_frames<JF, Ev> bf(ev);
    solve_status status = ev.status();
    if (!articulated_accelerations<JF, Sys>(bf, ev, ud) && status == solve_status::ok)
      status = solve_status::singular;
    if (status == solve_status::ok && !all_finite_matrix(ud)) status = solve_status::not_finite;
    if (status != solve_status::ok) ud.setConstant(std::numeric_limits<S>::quiet_NaN());
    return {ud, status};
  } else if constexpr (known_masses<Sys, Ev>()) {
    constexpr auto inverse =
        known_inverse<Sys, typename Ev::root, speeds_of<Ev>>;  // M^-1, a table of numbers
    if constexpr (!inverse.known)
      return speed_derivatives_at(mass_matrix_and_forcing_at<Sys, RestRates>(ev));  // singular
    else {
      const auto e = equations_along<Sys, RestRates, true, false>(ev, all_speeds<n>{});
      Eigen::Matrix<S, int(n), 1> ud = times_known<inverse>(e.f);
      solve_status status = e.status;
      if (status == solve_status::ok && !all_finite_matrix(ud)) status = solve_status::not_finite;
      if (status != solve_status::ok) ud.setConstant(std::numeric_limits<S>::quiet_NaN());
      return {ud, status};
    }
  } else
    return speed_derivatives_at(mass_matrix_and_forcing_at<Sys, RestRates>(ev));
}
}  // namespace detail

// tau = M u' - f at the evaluator's state, with its status
template <class Sys, Evaluator Ev>
inverse_result<typename Ev::scalar, Ev::nu> inverse_dynamics(const Ev& ev) {
  return detail::flat<typename Ev::scalar>(
      [&] { return detail::inverse_at<Sys, false, false, inverse_result<typename Ev::scalar, Ev::nu>>(ev); });
}

// f alone (tau at u' = 0 is -f), with its status
template <class Sys, Evaluator Ev>
forcing_result<typename Ev::scalar, Ev::nu> forcing(const Ev& ev) {
  return detail::flat<typename Ev::scalar>(
      [&] { return detail::inverse_at<Sys, true, true, forcing_result<typename Ev::scalar, Ev::nu>>(ev); });
}

// u' = M^-1 f at the evaluator's state, with its status
template <class Sys, Evaluator Ev>
forward_result<typename Ev::scalar, Ev::nu> forward_dynamics(const Ev& ev) {
  return detail::flat<typename Ev::scalar>([&] { return detail::forward_at<Sys, false>(ev); });
}

}  // namespace kane
#pragma GCC diagnostic pop
