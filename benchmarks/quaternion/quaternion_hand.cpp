// The free body by hand (quaternion.hpp): q normalised as kane does, q' = E(q)^T w / 2 in
// closed form, ^N v^P = v + ^N P^B^T (w x r) with the direction cosines from q.
#include <cmath>

#include "quaternion.hpp"

void quaternion::hand_rates(const input& in, output& out) {
  const double k =
      1 / std::sqrt(in.q[0] * in.q[0] + in.q[1] * in.q[1] + in.q[2] * in.q[2] + in.q[3] * in.q[3]);
  const double e0 = in.q[0] * k, e1 = in.q[1] * k, e2 = in.q[2] * k, e3 = in.q[3] * k;
  const double w1 = in.u[0], w2 = in.u[1], w3 = in.u[2];
  out.qd[0] = 0.5 * (-e1 * w1 - e2 * w2 - e3 * w3);
  out.qd[1] = 0.5 * (e0 * w1 - e3 * w2 + e2 * w3);
  out.qd[2] = 0.5 * (e3 * w1 + e0 * w2 - e1 * w3);
  out.qd[3] = 0.5 * (-e2 * w1 + e1 * w2 + e0 * w3);
  out.qd[4] = in.u[3], out.qd[5] = in.u[4], out.qd[6] = in.u[5];
  // w x r in B, then to N with the rows b_i of ^N P^B
  const double a = in.p[0], b = in.p[1], c = in.p[2];
  const double x = w2 * c - w3 * b, y = w3 * a - w1 * c, z = w1 * b - w2 * a;
  const double m00 = e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3, m01 = 2 * (e1 * e2 + e0 * e3),
               m02 = 2 * (e1 * e3 - e0 * e2), m10 = 2 * (e1 * e2 - e0 * e3),
               m11 = e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3, m12 = 2 * (e2 * e3 + e0 * e1),
               m20 = 2 * (e1 * e3 + e0 * e2), m21 = 2 * (e2 * e3 - e0 * e1),
               m22 = e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
  out.v[0] = in.u[3] + m00 * x + m10 * y + m20 * z;
  out.v[1] = in.u[4] + m01 * x + m11 * y + m21 * z;
  out.v[2] = in.u[5] + m02 * x + m12 * y + m22 * z;
}
