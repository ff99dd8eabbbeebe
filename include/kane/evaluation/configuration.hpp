// The dependent coordinates of holonomic constraints (speeds/holonomic.hpp)
// from the independent ones, by Newton's method on f(q) = 0:
//
//   kane::newton_result r = kane::solve_configuration<loop>(ev, s);
//
// Each step updates ev at s, evaluates f and J = df/dq_dep (symbolic, its
// zero pattern solved by structure: block_solve.hpp), and sets
// q_dep -= J^-1 f. It stops when max_k |f_k| <= tolerance (absolute, in the
// units of f): status ok, and s and ev hold the closed configuration.
// Otherwise: singular (J at or below the rank rule), not_finite (NaN or inf
// in s or on the way), not_converged (max_iterations steps without reaching
// the tolerance, as for a loop that cannot close); s holds the last iterate.
// No allocation; each step costs one update of ev.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>

#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/speeds/holonomic.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// Tolerance and step limit of Newton's method on holonomic constraints.
template <class S>
struct newton_options {
  // the bound on max_k |f_k|, in the units of f
  S tolerance = S(64) * std::numeric_limits<S>::epsilon();
  // the most Newton steps
  std::size_t max_iterations = 20;
};

// What Newton's method on holonomic constraints reached: status, steps, residual. Over lanes each
// lane stops on its own: a status and a residual per lane, the steps of the lane that took most.
template <class S>
struct newton_result {
  // ok, singular, not_finite or not_converged
  status_of<S> status;
  // the Newton steps taken
  std::size_t iterations;  // Newton steps taken
  S residual;              // max_k |f_k| at the last iterate (NaN if not finite)
};

namespace detail {
// f of H at ev's state; max_k |f_k| into residual and sum_k (f_k - f_k) into sum: 0 where every f_k
// is finite.
template <class H, class Ev, class F, class S>
KANE_ALWAYS_INLINE void constraint_values(const Ev& ev, F& f, S& residual, S& sum) {
  residual = S(0), sum = S(0);
  static_for<H::m>([&](auto k) {
    f[k][0] = eval_scalar(std::get<k>(H::equations), ev);
    using std::abs;
    residual = lane_traits<S>::select(abs(f[k][0]) > residual, abs(f[k][0]), residual);
    sum += f[k][0] - f[k][0];
  });
}
// J = df/dq_dep of H at ev's state, its entries known to be 0 or 1 left as the solve reads them.
template <class H, class Ev, class J>
KANE_ALWAYS_INLINE void constraint_jacobian(const Ev& ev, J& jac) {
  constexpr std::size_t m = H::m;
  static_for<m * m>([&](auto kj) {
    constexpr std::size_t k = kj / m, j = kj % m;
    if constexpr (newton_system<H>::m[k][j] == entry::other)
      jac[k][j] = eval_scalar(H::template jacobian<k, j>(), ev);
  });
}
// solve_configuration over lanes: a lane that stops keeps its iterate and its status, the others
// go on, until none is left.
template <class H, class Ev>
newton_result<typename Ev::scalar> newton_lanes(Ev& ev, typename Ev::state_type& s,
                                                const newton_options<typename Ev::scalar>& options) {
  using S = typename Ev::scalar;
  using St = status_of<S>;
  using traits = lane_traits<S>;
  constexpr std::size_t m = H::m;
  newton_result<S> out{St(solve_status::not_converged), 0, S(0)};
  auto active = traits::truth(true);
  const auto stop = [&](const typename traits::mask& where, const St& why) {  // active lanes in where
    const auto now = active && where;
    out.status.code = __builtin_convertvector(now.bits, typename St::codes) != 0 ? why.code : out.status.code;
    active = active && !where;
  };
  for (std::size_t step = 0;; ++step) {
    ev.update(s);
    table<S, m, 1> f, dq;
    table<S, m, m> jac{};
    S residual, sum;
    constraint_values<H>(ev, f, residual, sum);
    const auto finite = sum == S(0);
    out.iterations = step;
    out.residual = traits::select(
        active, traits::select(finite, residual, std::numeric_limits<S>::quiet_NaN()), out.residual);
    stop(!ok_of<S>(ev.status()), ev.status());  // the evaluator's own status first
    stop(!finite, St(solve_status::not_finite));
    stop(residual <= options.tolerance, St(solve_status::ok));
    if (step == options.max_iterations) stop(traits::truth(true), St(solve_status::not_converged));
    if (!any_of(active)) return out;
    constraint_jacobian<H>(ev, jac);
    const St solved = solve_structured<newton_system<H>>(jac, f, dq);
    stop(!ok_of<S>(solved), solved);
    static_for<m>([&](auto j) {
      S& q = s.q[H::dependents[j] - 1];
      q = traits::select(active, q - dq[j][0], q);
    });
  }
}
}  // namespace detail

// q_dep of s with f(q) = 0 by Newton's method from s; ev and s at the last iterate
template <Holonomic H, Evaluator Ev>
newton_result<typename Ev::scalar> solve_configuration(Ev& ev, typename Ev::state_type& s,
                                                       newton_options<typename Ev::scalar> options = {}) {
  using S = typename Ev::scalar;
  using Sys = detail::newton_system<H>;
  using St = typename Ev::state_type;
  constexpr std::size_t m = H::m;
  static_assert(H::last_dependent <= St::nq,
                "kane: a dependent coordinate is beyond the state; declare the state with NQ >= I");
  if constexpr (lane_traits<S>::width > 1) {
    return detail::newton_lanes<H>(ev, s, options);
  } else {
    newton_result<S> out{solve_status::not_converged, 0, S(0)};
    for (std::size_t step = 0;; ++step) {
      ev.update(s);
      detail::table<S, m, 1> f, dq;
      detail::table<S, m, m> jac{};
      S residual, sum;
      detail::constraint_values<H>(ev, f, residual, sum);
      out.iterations = step, out.residual = sum == S(0) ? residual : std::numeric_limits<S>::quiet_NaN();
      if (ev.status() != solve_status::ok || !(sum == S(0))) {  // the evaluator's own status first
        out.status = ev.status() != solve_status::ok ? ev.status() : solve_status::not_finite;
        return out;
      }
      if (residual <= options.tolerance) {
        out.status = solve_status::ok;
        return out;
      }
      if (step == options.max_iterations) {
        out.status = solve_status::not_converged;
        return out;
      }
      detail::constraint_jacobian<H>(ev, jac);
      if (const solve_status solved = detail::solve_structured<Sys>(jac, f, dq); solved != solve_status::ok) {
        out.status = solved;
        return out;
      }
      detail::static_for<m>([&](auto j) { s.q[H::dependents[j] - 1] -= dq[j][0]; });
    }
  }
}

}  // namespace kane
#pragma GCC diagnostic pop
