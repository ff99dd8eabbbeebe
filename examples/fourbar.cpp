// The four-bar linkage (models/fourbar.hpp): for a turn of the crank, Newton's method closes the
// loop (q2, q3 from q1), the velocity constraints give u2, u3 = A u1, and the coupler tip moves
// with ^N v^Q = v~_1 u1. Checked here against central differences of the solved configuration.
#include <cmath>
#include <cstdio>

#include "models/fourbar.hpp"

int main() {
  using namespace models::fourbar;
  state s;
  s.p = {0.3, 1.0, 0.8, 1.1};  // crank, coupler, rocker, ground: the crank turns fully
  s.q = {0.0, 0.3, 1.6};
  s.u = {1.0, 0.0, 0.0};
  evaluator ev;
  int failures = 0;
  std::printf("    q1       q2       q3    q2'/q1'  q3'/q1'   |v^Q|/q1'  Newton steps\n");
  for (int i = 0; i < 12; ++i) {
    s.q[0] = 2 * M_PI * i / 12;  // the last configuration is the guess for the next
    const auto closed = kane::solve_configuration<loop>(ev, s);
    const auto rates_ = kane::solve_constraints<rates>(ev);
    const auto V = kane::nonholonomic_partial_velocities<N, rates>(kane::velocity<N, Q>(), ev, rates_);
    // the same rate from two neighbouring solutions
    const double h = 1e-6;
    state sp = s, sm = s;
    evaluator ep, em;
    sp.q[0] += h, sm.q[0] -= h;
    const bool ok = closed.status == kane::solve_status::ok && rates_.status == kane::solve_status::ok &&
                    kane::solve_configuration<loop>(ep, sp).status == kane::solve_status::ok &&
                    kane::solve_configuration<loop>(em, sm).status == kane::solve_status::ok;
    const double fd = (sp.q[1] - sm.q[1]) / (2 * h);
    if (!ok || std::abs(fd - rates_.A(0, 0)) > 1e-6 * (1 + std::abs(fd))) ++failures;
    std::printf("% 8.4f % 8.4f % 8.4f % 8.4f % 8.4f % 10.5f  %zu\n", s.q[0], s.q[1], s.q[2], rates_.A(0, 0),
                rates_.A(1, 0), V.col(0).norm(), closed.iterations);
  }
  std::printf(failures ? "FAILED: %d configurations\n" : "loop closed and rates agree with differences\n",
              failures);
  return failures ? 1 : 0;
}
