// A free rigid body with Euler parameters (models/free_body.hpp): the kinematic equations
// q' = W(q) u (7 coordinates, 6 speeds: the held row keeps |q| = 1) integrated by RK4 for
// constant body rates u1..u3 and a constant velocity of the mass centre. With constant body
// rates the body turns about a fixed axis: after time t, ^N P^B is the rotation by |w| t
// about w applied to the start. Checked here against that closed form.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "models/free_body.hpp"

int main() {
  using namespace models::free_body;
  state s;
  s.q = {1, 0, 0, 0, 0, 0, 0};
  s.u = {0.3, -1.2, 0.8, 0.5, 0.0, -0.25};
  s.ud = {};
  s.p = {0.2, 0.1, -0.3};
  evaluator ev;
  auto rates = [&](const state& x) {
    ev.update(x);
    return ev.coordinate_rates();
  };
  const double dt = 1e-3;
  const int steps = 2000;
  int failures = 0;
  std::printf("     t      q1        q2        q3        q4       |q|-1     attitude error\n");
  for (int k = 1; k <= steps; ++k) {
    state a = s, b = s, c = s;
    const auto k1 = rates(s);
    for (int i = 0; i < 7; ++i) a.q[i] = s.q[i] + dt / 2 * k1[i];
    const auto k2 = rates(a);
    for (int i = 0; i < 7; ++i) b.q[i] = s.q[i] + dt / 2 * k2[i];
    const auto k3 = rates(b);
    for (int i = 0; i < 7; ++i) c.q[i] = s.q[i] + dt * k3[i];
    const auto k4 = rates(c);
    for (int i = 0; i < 7; ++i) s.q[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    if (k % 500 != 0) continue;
    const double t = k * dt;
    const Eigen::Vector3d w(s.u[0], s.u[1], s.u[2]);  // fixed in B and in N (B starts at N)
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix().transpose();
    const double error = (kane::direction_cosines<N, B>(s).eigen() - expected).norm();
    const double norm = std::sqrt(s.q[0] * s.q[0] + s.q[1] * s.q[1] + s.q[2] * s.q[2] + s.q[3] * s.q[3]) - 1;
    std::printf("%6.2f %9.5f %9.5f %9.5f %9.5f  %9.2e  %9.2e\n", t, s.q[0], s.q[1], s.q[2], s.q[3], norm,
                error);
    ev.update(s);
    const double centre = std::abs(s.q[4] - 0.5 * t) + std::abs(s.q[6] + 0.25 * t);
    if (!(ev.status() == kane::solve_status::ok && error < 1e-10 && std::abs(norm) < 1e-10 && centre < 1e-12))
      ++failures;
  }
  std::printf(failures == 0 ? "RK4 attitude matches the rotation about the fixed axis\n" : "FAILED\n");
  return failures == 0 ? 0 : 1;
}
