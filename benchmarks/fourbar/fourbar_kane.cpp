// kane's four-bar (fourbar.hpp, models/fourbar.hpp): solve_configuration, then solve_constraints,
// with an evaluator at the pose level (neither needs a velocity).
#include "../../examples/models/fourbar.hpp"
#include "fourbar.hpp"

void fourbar::kane_solve(const input& in, output& out) {
  using namespace models::fourbar;
  state s;
  s.q = in.q;
  s.p = in.p;
  kane::evaluator<state, kane::frames<A, B, C>, kane::level::pose, speeds> ev;
  kane::solve_configuration<loop>(ev, s);
  const auto sol = kane::solve_constraints<rates>(ev);
  out.q[0] = s.q[1], out.q[1] = s.q[2];
  out.A[0] = sol.A(0, 0), out.A[1] = sol.A(1, 0);
}
