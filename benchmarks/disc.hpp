// The rolling disc with contact coordinates (yaw q1, lean q2, spin q3,
// contact q4, q5; speeds u1..u3 = ^N w^R in L, u4 = q4', u5 = q5'): A of
// u_dep = A u_ind + B and the nonholonomic partial velocities of the centre in N.
#pragma once

#include <array>

namespace disc {
struct input {
  std::array<double, 5> q, u;
  double r;
};
struct output {
  double A[6];  // 2 x 3, row-major
  double V[9];  // 3 x 3, row-major: columns v~_1 v~_2 v~_3
};
void kane_partials(const input&, output&);
void hand_partials(const input&, output&);
}  // namespace disc
