// kane's rolling disc (disc_dynamics.hpp, models/disc.hpp): kane_rates is the integrator's
// right-hand side kane::constrained_motion, built once with the parameters and called per
// state (one pass: the pose, A and B from it, then the speeds and accelerations at the solved
// u_dep). kane_reduced_rates is what a user may write instead: A and B from a pose-level
// evaluator up to L (they read q1, q2 and r only), then one acceleration-level pass and
// Kane's reduced equations; both evaluators built per call.
#include "../../examples/models/disc.hpp"
#include "disc_dynamics.hpp"

namespace {
namespace d = models::disc;
using state = kane::state<double, 5, 5, 3>;
using evaluator = kane::evaluator<state, kane::frames<d::R>, kane::level::acceleration, d::speeds5>;
using rhs = kane::constrained_motion<d::system, d::rolling>;

state parameters() {
  state s;
  s.p = {disc_dynamics::p.r, disc_dynamics::p.m, disc_dynamics::p.g};
  return s;
}
rhs motion{parameters()};
}  // namespace

void disc_dynamics::kane_rates(const input& in, output& out) {
  motion(in.x, out.xd, 0.0);
  out.status = motion.status() == kane::solve_status::ok ? 0 : 1;
}

void disc_dynamics::kane_reduced_rates(const input& in, output& out) {
  state s;
  for (int i = 0; i < 5; ++i) s.q[i] = in.x[i];
  for (int i = 0; i < 3; ++i) s.u[i] = in.x[5 + i];
  s.p = {p.r, p.m, p.g};
  kane::evaluator<state, kane::frames<d::L>, kane::level::pose, d::speeds5> pose;
  pose.update(s);
  const auto sol = kane::solve_constraints<d::rolling>(pose);
  const Eigen::Vector2d dep = sol.A * Eigen::Vector3d(s.u[0], s.u[1], s.u[2]) + sol.B;
  s.u[3] = dep(0), s.u[4] = dep(1);
  evaluator ev;
  ev.update(s);
  const auto eq = kane::reduced_mass_matrix_and_forcing<d::system, d::rolling>(ev, sol);
  const auto ud = kane::speed_derivatives(eq.reduced).ud;
  const auto qd = ev.coordinate_rates();
  for (int i = 0; i < 5; ++i) out.xd[i] = qd[i];
  for (int i = 0; i < 3; ++i) out.xd[5 + i] = ud(i);
}
