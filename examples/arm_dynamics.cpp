// The 6R arm with masses (models/arm6_dynamics.hpp) driven by joint torques as
// inputs, under computed-torque control: at every step the controller asks
// kane::inverse_dynamics for tau = M u'_c - f with u'_c = q_d'' + kd (q_d' - u) +
// kp (q_d - q), and kane::motion integrates the arm with those torques as its
// inputs (RK4, dt = 1e-3, 2 s; the torques held over each step). From an error of
// up to 0.29 rad at the start, the tracking error must end below 1e-4 rad.
#include <array>
#include <cmath>
#include <cstdio>

#include "models/arm6_dynamics.hpp"
#include "rk4.hpp"

namespace arm = models::arm6;
using state = kane::state<double, 6, 6, 0, 6>;  // 6 inputs: the joint torques
// The arm is of joint form: its dynamics read an evaluator's pose alone (and the state's u, u');
// kane::motion reads q' of its evaluator as well (level::velocity).
template <kane::level L>
using evaluator = kane::evaluator<state, kane::frames<arm::B6>, L, kane::qdot_speeds<6>>;
using rhs = kane::motion<arm::driven, evaluator<kane::level::velocity>>;

// q_d(t) = 0.3 sin(t + i), and its rates
double desired(std::size_t i, double t, int order) {
  const double p = t + double(i);
  return 0.3 * (order == 0 ? std::sin(p) : order == 1 ? std::cos(p) : -std::sin(p));
}

int main() {
  state s;
  rhs arm_rhs(s);
  evaluator<kane::level::pose> controller;
  std::array<double, 12> x{};  // q = 0, u = 0: off the trajectory at the start
  const double dt = 1e-3, kp = 100, kd = 20;
  double error = 0;
  for (int step = 0; step < 2000; ++step) {
    const double t = step * dt;
    for (std::size_t i = 0; i < 6; ++i) {
      s.q[i] = x[i], s.u[i] = x[6 + i];
      s.ud[i] = desired(i, t, 2) + kd * (desired(i, t, 1) - x[6 + i]) + kp * (desired(i, t, 0) - x[i]);
    }
    controller.update(s);
    const auto [tau, status] = kane::inverse_dynamics<arm::links>(controller);
    if (status != kane::solve_status::ok) return 1;
    for (std::size_t i = 0; i < 6; ++i) arm_rhs.inputs()[i] = tau(Eigen::Index(i));
    if (step == 0)
      std::printf("tau at t = 0: %.6f %.6f %.6f %.6f %.6f %.6f\n", tau(0), tau(1), tau(2), tau(3), tau(4),
                  tau(5));
    rk4_step(arm_rhs, x, t, dt);  // the torques held over the step
    if (arm_rhs.status() != kane::solve_status::ok) return 1;
    error = 0;
    for (std::size_t i = 0; i < 6; ++i) error = std::fmax(error, std::abs(x[i] - desired(i, t + dt, 0)));
  }
  std::printf("largest joint error after 2 s: %.2e rad\n", error);
  const bool pass = error < 1e-4;
  std::printf(pass ? "tracking\n" : "FAILED\n");
  return pass ? 0 : 1;
}
