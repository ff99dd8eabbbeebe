// The rolling disc, the 6-revolute arm and the 3D double pendulum's equations of motion as C functions:
// compiled for a Cortex-M4 with arm-none-eabi-g++ -fno-exceptions -fno-rtti -Os, in float
// (KANE_EMBEDDED_SCALAR=float) or double, and run by the zero-allocation test.
#include "../../examples/models/arm6.hpp"
#include "../../examples/models/disc.hpp"
#include "../../examples/models/pendulum3d.hpp"

#ifndef KANE_EMBEDDED_SCALAR
#define KANE_EMBEDDED_SCALAR double
#endif
using real = KANE_EMBEDDED_SCALAR;

namespace {
using namespace models::arm6;
namespace disc = models::disc;
}  // namespace

// Everything of the arm in N: ^N P^B6 (9), r, v, a of the end point, ^N w^B6,
// ^N alpha^B6 (3 each), the Jacobian rows of the end point (18).
extern "C" void arm_step(const real* q, const real* qd, const real* qdd, real* out) {
  kane::state<real, 6> s;
  for (int i = 0; i < 6; ++i) s.q[i] = q[i], s.qd[i] = qd[i], s.qdd[i] = qdd[i];
  kane::evaluator<kane::state<real, 6>, kane::frames<B6>> ev;
  ev.update(s);
  const auto P = kane::direction_cosines<N, B6>(s);
  for (int i = 0; i < 9; ++i) out[i] = P(i % 3, i / 3);
  const kane::vec<N, real> v[] = {kane::express<N>(kane::position<O, End>(), ev),
                                  kane::express<N>(kane::velocity<N, End>(), ev),
                                  kane::express<N>(kane::acceleration<N, End>(), ev),
                                  kane::express<N>(kane::angular_velocity<N, B6>(), ev),
                                  kane::express<N>(kane::angular_acceleration<N, B6>(), ev)};
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 3; ++i) out[9 + 3 * k + i] = v[k][i];
  const auto J = kane::partial_velocities<N>(kane::velocity<N, End>(), ev);
  for (int i = 0; i < 18; ++i) out[24 + i] = J(i % 3, i / 3);
}

// A (6) and the nonholonomic partial velocities of the disc's centre (9) and their remainder (3).
extern "C" int disc_step(const real* q, const real* u, real radius, real* out) {
  kane::state<real, 5, 5, 1> s;
  for (int i = 0; i < 5; ++i) s.q[i] = q[i], s.u[i] = u[i];
  s.p[0] = radius;
  constexpr auto v = kane::velocity<disc::N, disc::Centre5>();
  using partials = kane::reads<kane::partials_of(v), kane::partials_of(disc::v_below)>;
  kane::evaluator_for<decltype(s), partials, disc::speeds5>::evaluator_type ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<disc::rolling>(ev);
  const auto V = kane::nonholonomic_partial_velocities<disc::N, disc::rolling>(v, ev, sol);
  for (int i = 0; i < 6; ++i) out[i] = sol.A(i % 2, i / 2);
  for (int i = 0; i < 9; ++i) out[6 + i] = V(i % 3, i / 3);
  const auto t = kane::nonholonomic_remainder<disc::N, disc::rolling>(v, ev, sol);
  for (int i = 0; i < 3; ++i) out[15 + i] = t(i);
  return sol.status == kane::solve_status::ok ? 0 : 1;
}

// Kane's equations of the 3D double pendulum as a right-hand side: x = (q, u) -> (q', u') (4 each);
// M alone, inverse dynamics, the forcing and forward dynamics.
extern "C" int pendulum_step(const real* x, const real* p, real* dxdt) {
  namespace m = models::pendulum3d;
  using state = kane::state<real, 2, 2, 21>;
  using evaluator =
      kane::evaluator<state, kane::frames<m::B>, kane::level::acceleration, kane::qdot_speeds<2>>;
  state s;
  for (int i = 0; i < 21; ++i) s.p[i] = p[i];
  kane::motion<m::system, evaluator> rhs(s);
  rhs(x, dxdt, real(0));
  s.q = {x[0], x[1]};  // M alone, from the pose
  kane::evaluator<state, kane::frames<m::B>, kane::level::pose, kane::qdot_speeds<2>> pose;
  pose.update(s);
  const auto mass = kane::mass_matrix<m::system>(pose);
  // inverse dynamics, the forcing alone and u' at (q, u, u' = dxdt's)
  s.u = {x[2], x[3]}, s.ud = {dxdt[2], dxdt[3]};
  evaluator ev;
  ev.update(s);
  const auto tau = kane::inverse_dynamics<m::system>(ev);
  const auto f = kane::forcing<m::system>(ev);
  const auto ud = kane::forward_dynamics<m::system>(ev);
  const bool ok = rhs.status() == kane::solve_status::ok && mass.status == kane::solve_status::ok &&
                  tau.status == kane::solve_status::ok && f.status == kane::solve_status::ok &&
                  ud.status == kane::solve_status::ok;
  return ok ? 0 : 1;
}
