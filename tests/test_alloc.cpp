// Evaluating kinematics allocates nothing: allocations.cpp counts, and the kernels of
// benchmarks/embedded/embedded.cpp (everything of the 6-revolute arm; the rolling disc's constraints and
// nonholonomic partial velocities; M, f and u' of the 3D double pendulum through
// kane::motion, its M alone by kane::mass_matrix, and kane::inverse_dynamics, kane::forcing and
// kane::forward_dynamics), and those of alloc_derivatives.cpp (the 6R arm's analytical derivatives and
// linearization, the pendulum's linearization by jets in batches) run between two readings of the
// counter.
// A plain program (no test framework allocating in between).
#include <cstdio>

#include "allocations.hpp"

extern "C" void arm_step(const double* q, const double* qd, const double* qdd, double* out);
extern "C" int disc_step(const double* q, const double* u, double radius, double* out);
extern "C" int pendulum_step(const double* x, const double* p, double* dxdt);
extern "C" int derivatives_step(const double* q, const double* qd, const double* r, const double* x,
                                const double* p, double* out);

int main() {
  const double q[6] = {0.1, -0.4, 0.8, 0.3, -1.2, 0.6}, qd[6] = {0.5, 0.2, -0.3, 1.0, 0.4, -0.7},
               qdd[6] = {0.1, -0.2, 0.3, -0.1, 0.2, 0.05};
  const double dq[5] = {0.3, 0.2, 1.0, 2.0, -1.0}, du[5] = {0.5, -1.5, 0.8, 0, 0};
  double arm[42], disc[18], dx[4], derivatives[2];
  const double torques[6] = {1.0, -2.0, 0.5, 0.3, -0.2, 0.1};
  const double x[4] = {1.2, -0.7, 0.5, 2.0},
               p[21] = {1.5,  1.4, 0.9, 1.0,  1.2,   0.7,   0.8,  0.9, 0.07, -0.06, 0.07,
                        0.66, 1.2, 1.0, 0.02, -0.03, -0.03, 9.81, 1.5, 0.2,  0.1};

  const long before = allocations::count();
  arm_step(q, qd, qdd, arm);
  const int status = disc_step(dq, du, 0.25, disc) + pendulum_step(x, p, dx) +
                     derivatives_step(q, qd, torques, x, p, derivatives);
  const long counted = allocations::count() - before;

  double sink = 0;
  for (double x : arm) sink += x;
  for (double x : disc) sink += x;
  for (double v : dx) sink += v;
  for (double v : derivatives) sink += v;
  std::printf("allocations during evaluation: %ld (checksum %.6f)\n", counted, sink);
  return counted == 0 && status == 0 ? 0 : 1;
}
