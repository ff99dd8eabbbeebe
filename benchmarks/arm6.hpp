// The 6-revolute chain of the benchmarks: axes z, y, y, x, y, x (each about
// the previous body's axis), joint i+1 at L_i along b_i x, the end point at
// L6 along b6 x. Every implementation fills the same outputs, in N.
#pragma once

#include <array>

namespace arm6 {
inline constexpr double L[6] = {0.3, 0.25, 0.2, 0.15, 0.1, 0.05};

struct input {
  std::array<double, 6> q, qd, qdd;
};
struct output {
  double R[9];  // columns e_B6,1..3 in N, column-major
  double p[3], w[3], v[3], alpha[3], a[3];
};

// Q1: R and p.  ALL: everything.
void kane_pose(const input&, output&);
void kane_all(const input&, output&);
void hand_pose(const input&, output&);
void hand_all(const input&, output&);
}  // namespace arm6
