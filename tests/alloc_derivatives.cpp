// Kernels of the zero-allocation test (test_alloc.cpp) for the derivatives: the driven 6R arm's
// analytical derivatives and its linearization with the joint torques as inputs, and the 3D double
// pendulum's linearization by jets in batches with a parameter as input.
#include <kane/kane.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "../examples/models/pendulum3d.hpp"

namespace {
namespace arm = models::arm6;
namespace pd = models::pendulum3d;
using arm_state = kane::state<double, 6, 6, 0, 6>;
using arm_evaluator =
    kane::evaluator<arm_state, kane::frames<arm::B6>, kane::level::pose, kane::qdot_speeds<6>>;
using torques = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>, kane::r<4>, kane::r<5>, kane::r<6>>;
}  // namespace

// A, B and du'/dx of the arm at q, q' with the torques r; A and B of the pendulum at x with the parameters p.
extern "C" int derivatives_step(const double* q, const double* qd, const double* r, const double* x,
                                const double* p, double* out) {
  arm_state s;
  for (std::size_t i = 0; i < 6; ++i) s.q[i] = q[i], s.u[i] = qd[i], s.r[i] = r[i];
  arm_evaluator ev;
  ev.update(s);
  const auto id = kane::inverse_dynamics_derivatives<arm::driven>(ev);
  const auto fd = kane::forward_dynamics_derivatives<arm::driven>(ev);
  const auto lin = kane::linearize<arm::driven, arm_evaluator, torques>(s);
  pd::state t;
  for (std::size_t i = 0; i < 2; ++i) t.q[i] = x[i], t.u[i] = x[2 + i];
  for (std::size_t i = 0; i < t.p.size(); ++i) t.p[i] = p[i];
  const auto plin = kane::linearize<pd::system, pd::evaluator, kane::inputs<pd::p<19>>>(t);
  out[0] = id.dtau_dq(1, 2) + fd.dud_du(3, 4) + lin.A(8, 3) + lin.B(9, 2);
  out[1] = plin.A(2, 1) + plin.B(3, 0);
  const bool ok = id.status == kane::solve_status::ok && fd.status == kane::solve_status::ok &&
                  lin.status == kane::solve_status::ok && plin.status == kane::solve_status::ok;
  return ok ? 0 : 1;
}
