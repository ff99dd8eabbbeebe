// kane's rolling disc (disc.hpp, models/disc.hpp). A and the nonholonomic partial
// velocities depend on q1, q2 and r alone: the evaluator holds the frames up to
// L (the spin angle q3 turns nothing they read) at the pose level (W needs q
// only; no velocity is computed).
#include "../examples/models/disc.hpp"
#include "disc.hpp"

namespace {
using namespace models::disc;
using state = kane::state<double, 5, 5, 1>;
}  // namespace

void disc::kane_partials(const input& in, output& out) {
  state s;
  s.q = in.q;
  s.u = in.u;
  s.p = {in.r};
  kane::evaluator<state, kane::frames<L>, kane::level::pose, speeds5> ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<rolling>(ev);
  const auto V = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Centre5>(), ev, sol);
  Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(out.A) = sol.A;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(out.V) = V;
}
