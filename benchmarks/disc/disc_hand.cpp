// The rolling disc by hand (disc.hpp): the closed forms of A and of the nonholonomic partial
// velocities of the centre.
#include <cmath>
#include <cstdint>
#include <limits>

#include "../common/checked.hpp"
#include "disc.hpp"

// Closed form in plain doubles: u4 = r c1 (u2 - t2 u3), u5 = r s1 (u2 - t2 u3), so v~_1 = -r l2,
// v~_2 = r (c1 n1 + s1 n2), v~_3 = 0; sin and cos of q1 and q2, one division, seven products.
void disc::hand_partials(const input& in, output& out) {
  const double c1 = std::cos(in.q[0]), s1 = std::sin(in.q[0]), c2 = std::cos(in.q[1]), s2 = std::sin(in.q[1]);
  const double rc1 = in.r * c1, rs1 = in.r * s1, t2 = s2 / c2;
  const double rs2 = in.r * s2;  // every input read before the first store (out may alias in)
  out.A[0] = 0, out.A[1] = rc1, out.A[2] = -rc1 * t2;
  out.A[3] = 0, out.A[4] = rs1, out.A[5] = -rs1 * t2;
  out.V[0] = rs1 * c2, out.V[1] = rc1, out.V[2] = 0;
  out.V[3] = -rc1 * c2, out.V[4] = rs1, out.V[5] = 0;
  out.V[6] = -rs2, out.V[7] = 0, out.V[8] = 0;
}

// The same with what a careful user adds (../common/checked.hpp): q, u, r and A, V tested finite,
// else A, V NaN and status 1.
[[gnu::flatten]] void disc::hand_partials_checked(const input& in, output& out) {
  std::uint64_t bad = bench::infinite_bit(in.r);
  for (const double x : in.q) bad |= bench::infinite_bit(x);
  for (const double x : in.u) bad |= bench::infinite_bit(x);
  hand_partials(in, out);
  for (const double x : out.A) bad |= bench::infinite_bit(x);
  for (const double x : out.V) bad |= bench::infinite_bit(x);
  const bool finite = (bad >> 63) == 0;
  if (!finite) {
    for (double& x : out.A) x = std::numeric_limits<double>::quiet_NaN();
    for (double& x : out.V) x = std::numeric_limits<double>::quiet_NaN();
  }
  out.status = finite ? 0 : 1;
}
