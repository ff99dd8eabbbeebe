// The free body's motion, compiled once (the declarations: free_body_motion.hpp).
#include "free_body_motion.hpp"

#include "free_body.hpp"

namespace models::free_body {
namespace {
using m_ = kane::parameter<4>;  // after the model's a, b, c (p1..p3)
using I1_ = kane::parameter<5>;
using I2_ = kane::parameter<6>;
using I3_ = kane::parameter<7>;
using body = kane::rigid_body<B, Bo, m_{}, kane::inertia<B, Bo, I1_{}, I2_{}, I3_{}>>;
using body_state = kane::state<double, 7, 6, 7>;
using body_evaluator = kane::evaluator<body_state, kane::frames<B>, kane::level::acceleration, speeds>;
using rhs = kane::motion<kane::system<body>, body_evaluator>;

body_state at(const mass_properties& b, const motion_vector& x) {
  body_state s;
  s.p = {0, 0, 0, b.m, b.I1, b.I2, b.I3};
  for (std::size_t i = 0; i < 7; ++i) s.q[i] = x[i];
  for (std::size_t i = 0; i < 6; ++i) s.u[i] = x[7 + i];
  return s;
}
}  // namespace

kane::solve_status motion_rates(const mass_properties& b, const motion_vector& x, motion_vector& dxdt) {
  rhs f(at(b, x));
  f(x, dxdt, 0.0);
  return f.status();
}

double kinetic_energy(const mass_properties& b, const motion_vector& x) {
  body_evaluator ev;
  ev.update(at(b, x));
  return kane::kinetic_energy<kane::system<body>>(ev);
}
}  // namespace models::free_body
