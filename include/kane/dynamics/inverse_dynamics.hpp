// Inverse dynamics at the evaluator's state, with the status of the evaluator (or not_finite):
//
//   kane::inverse_dynamics<Sys>(ev)  tau = M u' - f: the generalized forces that,
//                                    added to the system's loads, give the state's u'
//   kane::forcing<Sys>(ev)           f alone (tau at u' = 0 is -f, the bias)
//
// For a system of joint form (joint_form.hpp) tau and f come from one outward and
// one inward pass (rnea.hpp); otherwise from Kane's sums of f alone (sums.hpp), with the
// state's u' in the accelerations for tau: M is not formed. Each returns a named result
// (results.hpp): {tau, status} and {f, status}; when the status is not ok the numbers are NaN.
#pragma once

#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// tau at the state's u' (Rest false) or at u' = 0 (Rest true); -tau with Negated; as Out.
template <class Sys, rates Rates, sign Sign, class Out, class Ev>
Out inverse_at(const Ev& ev) {
  constexpr bool Rest = Rates == rates::at_rest, Negated = Sign == sign::minus;
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  Eigen::Matrix<S, int(n), 1> tau;
  if constexpr (recursive_form<Sys, Ev>) {
    static_assert(system_checked<Sys, speeds_of<Ev>>(typename Sys::items{}));
    using JF = joint_form_of<Sys, Ev>;
    const body_frames<JF, Ev> bf(ev);
    joint_forces<Rates, JF, Sys, Sign>(bf, ev, tau);
  } else if constexpr (admitted<Sys, speeds_of<Ev>>()) {
    // f with the bias accelerations (Rest), or with the state's u' in them: -tau, no M
    constexpr rates in_f = Rest ? rates::of_state : rates::at_rest;
    const auto e = equations_along<Sys, in_f, parts::forcing>(ev, all_speeds<n>{});
    if constexpr (Negated)
      tau = e.f;
    else
      tau = -e.f;
  }
  const auto status = finished(tau, ev.status());
  return {tau, status};
}

}  // namespace detail

// tau = M u' - f at the evaluator's state, with its status
template <System Sys, Evaluator Ev>
inverse_result<typename Ev::scalar, Ev::nu> inverse_dynamics(const Ev& ev) {
  return detail::flat<typename Ev::scalar>([&] {
    return detail::inverse_at<Sys, detail::rates::of_state, detail::sign::plus,
                              inverse_result<typename Ev::scalar, Ev::nu>>(ev);
  });
}

// f alone (tau at u' = 0 is -f), with its status
template <System Sys, Evaluator Ev>
forcing_result<typename Ev::scalar, Ev::nu> forcing(const Ev& ev) {
  return detail::flat<typename Ev::scalar>([&] {
    return detail::inverse_at<Sys, detail::rates::at_rest, detail::sign::minus,
                              forcing_result<typename Ev::scalar, Ev::nu>>(ev);
  });
}

}  // namespace kane
#pragma GCC diagnostic pop
