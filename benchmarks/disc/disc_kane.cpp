// kane's rolling disc (disc.hpp, models/disc.hpp), as examples/rolling_disc.cpp writes it: the
// evaluator for what the partial velocities of the centre and of the contact read (their
// frames, up to L, at the pose level: A and the partials depend on q1, q2 and r alone).
#include "../../examples/models/disc.hpp"
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
  constexpr auto v5 = kane::velocity<N, Centre5>();
  using partials = kane::reads<kane::partials_of(v5), kane::partials_of(v_below)>;
  kane::evaluator_for<state, partials, speeds5>::evaluator_type ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<rolling>(ev);
  const auto V = kane::nonholonomic_partial_velocities<N, rolling>(v5, ev, sol);
  Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(out.A) = sol.A;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(out.V) = V;
  out.status = sol.status == kane::solve_status::ok ? 0 : 1;
}
