// The three small models by hand (small_models.hpp); s_i, c_i are sin q_i, cos q_i.
// top: Euler's equations about O, I1 = I2 = 0.02 + m l^2 = 0.155, I3 = 0.035, the gravity torque
//   of Co l c3 x (-m g n3) = m g l s2 (c3 c1 - s3 c2) (n3 = s2 s3 c1 + s2 c3 c2 + c2 c3):
//   q1' = (s3 u1 + c3 u2) / s2,  q2' = c3 u1 - s3 u2,  q3' = u3 - c2 q1',
//   u1' = ((I1 - I3) u2 u3 + m g l s2 c3) / I1,  u2' = ((I3 - I1) u1 u3 - m g l s2 s3) / I1,  u3' = 0.
// spacecraft: a gyrostat. I = I_B + I_W = diag(1.21, 1.51, 1.92) about Bo, the wheel's axial
//   inertia J = 0.02; H = I w + J u7 b3 is constant in N and the wheel's axial equation is
//   J (w3 + u7)' = 0, so with w = (u1, u2, u3) and q = (q1, q2, q3, q4):
//   q' = E(q) w / 2 (E = [-q2 -q3 -q4; q1 -q4 q3; q4 q1 -q2; -q3 q2 q1]),  (q5, q6, q7)' = (u4, u5, u6),
//   I1 u1' = (I2 - I3) u2 u3 - J u7 u2,  I2 u2' = (I3 - I1) u3 u1 + J u7 u1,
//   (I3 - J) u3' = (I1 - I2) u1 u2,  u7' = -u3',  (u4, u5, u6)' = 0.
// pendulum: with a = (m1 + m2) L1^2 + m2 L2^2, b = m2 L1 L2, d = m2 L2^2, G1 = (m1 + m2) g L1,
//   G2 = m2 g L2 and s12 = sin(q1 + q2): M = [a + 2 b c2, d + b c2; d + b c2, d],
//   f = (b s2 u2 (2 u1 + u2) - G1 s1 - G2 s12, -b s2 u1^2 - G2 s12), solved by Cramer's rule with
//   det M = d (a - d) - b^2 c2^2.
// pendulum_absolute: with A = (m1 + m2) L1^2, b, d, G1, G2 as above and s12, c12 of q1 - q2:
//   M = [A, b c12; b c12, d], f = (-b s12 u2^2 - G1 s1, b s12 u1^2 - G2 s2), det M = A d - b^2 c12^2.
// Each has a checked twin (../common/checked.hpp).
// Plain doubles; sin and cos of q2, q3 (the top), q1, q2 (the pendulum; s12 from them).
#include <cmath>

#include "../common/checked.hpp"
#include "small_models.hpp"

void small::top_hand(const top_in& in, top_out& out) {
  constexpr double m = 1.5, l = 0.3, g = 9.81, I1 = 0.02 + m * l * l, I3 = 0.035;
  constexpr double k = (I1 - I3) / I1, h = m * g * l / I1;
  const double* x = in.x.data();
  const double s2 = std::sin(x[1]), c2 = std::cos(x[1]), s3 = std::sin(x[2]), c3 = std::cos(x[2]);
  const double u1 = x[3], u2 = x[4], u3 = x[5];
  const double q1d = (s3 * u1 + c3 * u2) / s2;
  out.xd[0] = q1d;
  out.xd[1] = c3 * u1 - s3 * u2;
  out.xd[2] = u3 - c2 * q1d;
  out.xd[3] = k * u2 * u3 + h * s2 * c3;
  out.xd[4] = -k * u1 * u3 - h * s2 * s3;
  out.xd[5] = 0;
}

void small::spacecraft_hand(const spacecraft_in& in, spacecraft_out& out) {
  constexpr double J = 0.02, I1 = 1.2 + 0.01, I2 = 1.5 + 0.01, I3 = 1.9 + J;
  const double* x = in.x.data();
  const double e0 = x[0], e1 = x[1], e2 = x[2], e3 = x[3];
  const double w1 = x[7], w2 = x[8], w3 = x[9], u7 = x[13];
  out.xd[0] = 0.5 * (-e1 * w1 - e2 * w2 - e3 * w3);
  out.xd[1] = 0.5 * (e0 * w1 - e3 * w2 + e2 * w3);
  out.xd[2] = 0.5 * (e3 * w1 + e0 * w2 - e1 * w3);
  out.xd[3] = 0.5 * (-e2 * w1 + e1 * w2 + e0 * w3);
  out.xd[4] = x[10], out.xd[5] = x[11], out.xd[6] = x[12];
  const double w3d = ((I1 - I2) / (I3 - J)) * w1 * w2;
  out.xd[7] = -w2 * ((I3 - I2) * w3 + J * u7) * (1 / I1);
  out.xd[8] = w1 * ((I3 - I1) * w3 + J * u7) * (1 / I2);
  out.xd[9] = w3d;
  out.xd[10] = 0, out.xd[11] = 0, out.xd[12] = 0;
  out.xd[13] = -w3d;
}

void small::pendulum_hand(const pendulum_in& in, pendulum_out& out) {
  constexpr double m1 = 1.0, m2 = 0.7, L1 = 1.2, L2 = 0.8, g = 9.81;
  constexpr double a = (m1 + m2) * L1 * L1 + m2 * L2 * L2, b = m2 * L1 * L2, d = m2 * L2 * L2;
  constexpr double G1 = (m1 + m2) * g * L1, G2 = m2 * g * L2;
  const double* x = in.x.data();
  const double s1 = std::sin(x[0]), c1 = std::cos(x[0]), s2 = std::sin(x[1]), c2 = std::cos(x[1]);
  const double u1 = x[2], u2 = x[3];
  const double s12 = s1 * c2 + c1 * s2, bs2 = b * s2, bc2 = b * c2;
  const double f1 = bs2 * u2 * (2 * u1 + u2) - G1 * s1 - G2 * s12, f2 = -bs2 * u1 * u1 - G2 * s12;
  const double m11 = a + 2 * bc2, m12 = d + bc2;
  const double inv = 1 / (d * (a - d) - bc2 * bc2);
  out.xd[0] = u1;
  out.xd[1] = u2;
  out.xd[2] = (d * f1 - m12 * f2) * inv;
  out.xd[3] = (m11 * f2 - m12 * f1) * inv;
}

void small::pendulum_absolute_hand(const pendulum_in& in, pendulum_out& out) {
  constexpr double m1 = 1.0, m2 = 0.7, L1 = 1.2, L2 = 0.8, g = 9.81;
  constexpr double A = (m1 + m2) * L1 * L1, b = m2 * L1 * L2, d = m2 * L2 * L2;
  constexpr double G1 = (m1 + m2) * g * L1, G2 = m2 * g * L2;
  const double* x = in.x.data();
  const double s1 = std::sin(x[0]), c1 = std::cos(x[0]), s2 = std::sin(x[1]), c2 = std::cos(x[1]);
  const double u1 = x[2], u2 = x[3];
  const double s12 = s1 * c2 - c1 * s2, bc12 = b * (c1 * c2 + s1 * s2), bs12 = b * s12;
  const double f1 = -bs12 * u2 * u2 - G1 * s1, f2 = bs12 * u1 * u1 - G2 * s2;
  const double inv = 1 / (A * d - bc12 * bc12);
  out.xd[0] = u1;
  out.xd[1] = u2;
  out.xd[2] = (d * f1 - bc12 * f2) * inv;
  out.xd[3] = (A * f2 - bc12 * f1) * inv;
}

[[gnu::flatten]] void small::top_hand_checked(const top_in& in, top_out& out) {
  bench::checked(in, out, small::top_hand);
}
[[gnu::flatten]] void small::spacecraft_hand_checked(const spacecraft_in& in, spacecraft_out& out) {
  bench::checked(in, out, small::spacecraft_hand);
}
[[gnu::flatten]] void small::pendulum_hand_checked(const pendulum_in& in, pendulum_out& out) {
  bench::checked(in, out, small::pendulum_hand);
}
[[gnu::flatten]] void small::pendulum_absolute_hand_checked(const pendulum_in& in, pendulum_out& out) {
  bench::checked(in, out, small::pendulum_absolute_hand);
}
