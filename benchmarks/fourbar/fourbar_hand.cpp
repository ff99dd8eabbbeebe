// The four-bar by hand (fourbar.hpp): f and its Jacobian in closed form, the 2 x 2 step by
// Cramer's rule, sin and cos of q1 once and of q2, q3 once per step.
#include <cmath>
#include <limits>

#include "fourbar.hpp"

void fourbar::hand_solve(const input& in, output& out) {
  const double a = in.p[0], b = in.p[1], c = in.p[2], d = in.p[3];
  const double ac1 = a * std::cos(in.q[0]), as1 = a * std::sin(in.q[0]);
  double q2 = in.q[1], q3 = in.q[2], j11 = 0, j12 = 0, j21 = 0, j22 = 0;
  for (int step = 0; step <= 20; ++step) {
    const double c2 = std::cos(q2), s2 = std::sin(q2), c3 = std::cos(q3), s3 = std::sin(q3);
    const double f1 = ac1 + b * c2 - c * c3 - d, f2 = as1 + b * s2 - c * s3;
    j11 = -b * s2, j12 = c * s3, j21 = b * c2, j22 = -c * c3;
    if (std::fmax(std::fabs(f1), std::fabs(f2)) <= 64 * std::numeric_limits<double>::epsilon()) break;
    const double inv = 1 / (j11 * j22 - j12 * j21);
    q2 -= (j22 * f1 - j12 * f2) * inv;
    q3 -= (j11 * f2 - j21 * f1) * inv;
  }
  // J [u2 u3]^T = -[-a s1, a c1]^T u1
  const double inv = 1 / (j11 * j22 - j12 * j21);
  out.q[0] = q2, out.q[1] = q3;
  out.A[0] = (j22 * as1 + j12 * ac1) * inv;
  out.A[1] = (-j21 * as1 - j11 * ac1) * inv;
}
