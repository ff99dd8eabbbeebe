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

// What Newton's method on holonomic constraints reached: status, steps, residual.
template <class S>
struct newton_result {
  // ok, singular, not_finite or not_converged
  solve_status status;
  // the Newton steps taken
  std::size_t iterations;  // Newton steps taken
  S residual;              // max_k |f_k| at the last iterate (NaN if not finite)
};

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
  newton_result<S> out{solve_status::not_converged, 0, S(0)};
  for (std::size_t step = 0;; ++step) {
    ev.update(s);
    detail::table<S, m, 1> f, dq;
    detail::table<S, m, m> jac{};
    S residual = S(0), sum = S(0);
    detail::static_for<m>([&](auto k) {
      f[k][0] = detail::eval_scalar(std::get<k>(H::equations), ev);
      using std::abs;
      residual = abs(f[k][0]) > residual ? abs(f[k][0]) : residual;
      sum += f[k][0] - f[k][0];
    });
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
    detail::static_for<m * m>([&](auto kj) {
      constexpr std::size_t k = kj / m, j = kj % m;
      if constexpr (Sys::m[k][j] == detail::entry::other) {
        constexpr auto c = H::template jacobian<k, j>();
        jac[k][j] = detail::eval_scalar(c, ev);
      }
    });
    if (const solve_status solved = detail::solve_structured<Sys>(jac, f, dq); solved != solve_status::ok) {
      out.status = solved;
      return out;
    }
    detail::static_for<m>([&](auto j) { s.q[H::dependents[j] - 1] -= dq[j][0]; });
  }
}

}  // namespace kane
#pragma GCC diagnostic pop
