// Forward dynamics at the evaluator's state: u' = M^-1 f with the status of the evaluator, or
// singular (M not positive definite), or not_finite.
//
//   kane::forward_dynamics<Sys>(ev)  {ud, status}
//
// Above articulated_above speeds of a system of joint form, u' comes from articulated bodies
// (tree/aba.hpp); where Kane's sums know M at compile time, from M^-1 as a table of numbers;
// otherwise from M and f and a fixed-size Cholesky factorization. When the status is not ok, u'
// is NaN.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/tree/aba.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/dynamics/results.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// u' = M^-1 f; rates::at_rest or zero: the state's u' is 0 (zero: as in motion.hpp). Finish false:
// u' unchecked, as speed_derivatives_at (checking::at_end: f unchecked too).
template <class Sys, rates Rates, class Ev, bool Finish = true, checking Check = checking::each>
forward_result<typename Ev::scalar, Ev::nu> forward_at(const Ev& ev) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  if constexpr (recursive_form<Sys, Ev> && !free_joint<Sys, Ev> && (n > articulated_above)) {
    static_assert(system_checked<Sys, speeds_of<Ev>>(typename Sys::items{}));
    using JF = joint_form_of<Sys, Ev>;
    Eigen::Matrix<S, int(n), 1> ud;
    const body_frames<JF, Ev> bf(ev);
    status_of<S> status = ev.status();
    fail_unless(status, articulated_accelerations<JF, Sys>(bf, ev, ud), solve_status::singular);
    if constexpr (Finish) status = finished(ud, status);
    return {ud, status};
  } else if constexpr (known_masses<Sys, Ev>()) {
    constexpr auto inverse =
        known_inverse<Sys, typename Ev::root, speeds_of<Ev>>;  // M^-1, a table of numbers
    if constexpr (!inverse.known)
      return speed_derivatives_at<Finish>(mass_matrix_and_forcing_at<Sys, Rates, Check>(ev));  // singular
    else {
      const auto e = equations_along<Sys, Rates, parts::forcing>(ev, all_speeds<n>{});
      return forward_result<S, n>{times_known<inverse>(e.f), e.status};  // finish_forward checks it
    }
  } else
    return speed_derivatives_at<Finish>(mass_matrix_and_forcing_at<Sys, Rates, Check>(ev));
}
// u' of forward_at checked finite by the caller, in place (a copy of the result would read whole
// what was written in blocks): where M^-1 is a table of numbers.
template <class Sys, class Ev, class R>
KANE_ALWAYS_INLINE void finish_forward(R& r) {
  if constexpr (!(recursive_form<Sys, Ev> && !free_joint<Sys, Ev> && (Ev::nu > articulated_above)) &&
                known_masses<Sys, Ev>()) {
    if constexpr (known_inverse<Sys, typename Ev::root, speeds_of<Ev>>.known)
      r.status = finished(r.ud, r.status);
  }
}
}  // namespace detail

// u' = M^-1 f at the evaluator's state, with its status
template <System Sys, Evaluator Ev>
forward_result<typename Ev::scalar, Ev::nu> forward_dynamics(const Ev& ev) {
  return detail::flat<typename Ev::scalar>([&] {
    auto r = detail::forward_at<Sys, detail::rates::of_state>(ev);
    detail::finish_forward<Sys, Ev>(r);
    return r;
  });
}

}  // namespace kane
#pragma GCC diagnostic pop
