// Kane's dynamical equations Fr + Fr* = 0 for the speeds of the evaluator, as
// M(q, t) u' = f(q, u, t) in the root frame of the evaluator's tree: regrouped over
// the tree for a system of joint form (crba.hpp, rnea.hpp), else Kane's sums
// (sums.hpp); u' = M^-1 f by a fixed-size Cholesky factorization.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kane/detail/inline.hpp"
#include "kane/detail/invert.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/sums/sums.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/detail/tree/crba.hpp"
#include "kane/dynamics/detail/tree/joint_form.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/evaluation/tables.hpp"
#include "kane/frames/vec.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// M alone, M_rs = sum m v_r . v_s + w_r . I . w_s: the partial velocities need the pose only,
// so an evaluator of any level will do (level::pose computes least).

namespace detail {
// M by composite bodies and f by inward sums (crba.hpp, rnea.hpp), written in place into Out:
// equations_of_motion, or mass_matrix_only (M alone). checking::at_end: f unchecked (the caller
// checks M^-1 f).
template <class Sys, class Out, checking Check = checking::each, class Ev>
Out recursive_equations(const Ev& ev) {
  using JF = joint_form_of<Sys, Ev>;
  static_assert(detail::system_checked<Sys, speeds_of<Ev>>(typename Sys::items{}));
  Out out;
  out.status = ev.status();
  const body_frames<JF, Ev> bf(ev);
  composite_mass_matrix<JF, Sys>(bf, ev, out.M);
  auto finite = finite_diagonal(out.M);
  if constexpr (requires { out.f; }) {
    joint_forces<rates::at_rest, JF, Sys, sign::minus>(bf, ev, out.f);
    if constexpr (Check == checking::each) finite = finite && all_finite_matrix(out.f);
  }
  fail_unless(out.status, finite, solve_status::not_finite);
  return out;
}
template <class Sys, rates Rates, checking Check = checking::each, class Ev>
equations_of_motion<typename Ev::scalar, Ev::nu> mass_matrix_and_forcing_at(const Ev& ev) {
  if constexpr (!admitted<Sys, speeds_of<Ev>>())
    return {};
  else if constexpr (recursive_form<Sys, Ev>)
    return recursive_equations<Sys, equations_of_motion<typename Ev::scalar, Ev::nu>, Check>(ev);
  else
    return equations_along<Sys, Rates, parts::both, Check>(ev, all_speeds<Ev::nu>{});
}
}  // namespace detail

// M and f of the system Sys at the evaluator's state (level::acceleration).
template <System Sys, Evaluator Ev>
equations_of_motion<typename Ev::scalar, Ev::nu> mass_matrix_and_forcing(const Ev& ev) {
  return detail::flat<typename Ev::scalar>(
      [&] { return detail::mass_matrix_and_forcing_at<Sys, detail::rates::of_state>(ev); });
}

// M alone of the system Sys at the evaluator's state (any level)
template <System Sys, Evaluator Ev>
mass_matrix_only<typename Ev::scalar, Ev::nu> mass_matrix(const Ev& ev) {
  using S = typename Ev::scalar;
  using out = mass_matrix_only<S, Ev::nu>;
  return detail::flat<S>([&]() -> out {
    if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>())
      return {};
    else if constexpr (detail::recursive_form<Sys, Ev>)
      return detail::recursive_equations<Sys, out>(ev);
    else {
      const auto e = detail::equations_along<Sys, detail::rates::at_rest, detail::parts::mass_matrix>(
          ev, detail::all_speeds<Ev::nu>{});
      return {e.M, e.status};
    }
  });
}

namespace detail {
// speed_derivatives in the caller's body, with no branch around a store (after it, motion's local
// evaluator's unread stores stay dead: motion.hpp). Finish false: u' unchecked, for a caller that
// checks and spoils it with its other results (write_checked_rates).
template <bool Finish = true, class S, std::size_t N>
forward_result<S, N> speed_derivatives_at(const equations_of_motion<S, N>& e) {
  Eigen::Matrix<S, int(N), 1> ud = Eigen::Matrix<S, int(N), 1>::Constant(std::numeric_limits<S>::quiet_NaN());
  using detail::solve_positive_definite;  // jets: theirs (argument-dependent lookup)
  const auto positive = solve_positive_definite(e.M, e.f, ud);
  status_of<S> status = e.status;
  fail_unless(status, positive, solve_status::singular);
  if constexpr (lane_traits<S>::width > 1 || !Finish)
    return {ud, Finish ? finished(ud, status) : status};
  else {
    fail_unless(status, detail::all_finite_numbers(ud), solve_status::not_finite);
    spoil_unless(ud, opaque_ok<S>(status));
    return {ud, status};
  }
}
}  // namespace detail

// u' = M^-1 f by a Cholesky factorization of fixed size; singular if M is not
// positive definite (a speed that moves no mass), with NaN.
template <class S, std::size_t N>
forward_result<S, N> speed_derivatives(const equations_of_motion<S, N>& e) {
  return detail::flat<S>([&] { return detail::speed_derivatives_at(e); });
}

}  // namespace kane
#pragma GCC diagnostic pop
