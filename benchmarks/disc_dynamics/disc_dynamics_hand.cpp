// The rolling disc's forward dynamics by hand (disc_dynamics.hpp). With s_i, c_i of q_i and
// t2 = s2 / c2, the kinematic equations and the constraints give
//   q1' = u3 / c2,  q2' = u1,  q3' = u2 - t2 u3,  (q4', q5') = r q3' (c1, s1),
// and Kane's equations have the diagonal mass matrix m r^2 diag(5/4, 3/2, 1/4) (v_centre =
// r (u2 l1 - u1 l2)), so each u' is its forcing over its mass (derived with SymPy):
//   u1' = (4 (g / r) s2 + u3 (6 u2 - t2 u3)) / 5,  u2' = -2 u1 u3 / 3,  u3' = u1 (t2 u3 - 2 u2).
// Plain doubles: sin and cos of q1 and q2 (q3 enters nothing), one division 1 / (r c2) for
// both 1 / c2 and 1 / r; m cancels.
#include <cmath>

#include "../common/checked.hpp"
#include "disc_dynamics.hpp"

void disc_dynamics::hand_rates(const input& in, output& out) {
  const double* x = in.x.data();
  const double r = p.r, g = p.g;
  const double c1 = std::cos(x[0]), s1 = std::sin(x[0]), c2 = std::cos(x[1]), s2 = std::sin(x[1]);
  const double u1 = x[5], u2 = x[6], u3 = x[7];
  const double d = 1 / (r * c2), ic2 = r * d, t2 = s2 * ic2;  // 1 / (r c2), 1 / c2, tan q2
  const double spin = u2 - t2 * u3;                           // q3'
  out.xd[0] = u3 * ic2;
  out.xd[1] = u1;
  out.xd[2] = spin;
  out.xd[3] = r * c1 * spin;
  out.xd[4] = r * s1 * spin;
  out.xd[5] = 0.2 * (4 * g * c2 * d * s2 + u3 * (6 * u2 - t2 * u3));
  out.xd[6] = (-2.0 / 3) * u1 * u3;
  out.xd[7] = u1 * (t2 * u3 - 2 * u2);
}

[[gnu::flatten]] void disc_dynamics::hand_rates_checked(const input& in, output& out) {
  bench::checked(in, out, hand_rates);
}
