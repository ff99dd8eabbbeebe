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
  double R[9];      // Q1: columns e_B6,1..3 in N, column-major
  double p[3];      // Q1: the end point
  double w[3];      // Q2: ^N w^B6
  double v[3];      // Q2: ^N v^End
  double J[36];     // Q3: rows w_r (B6) over v_r (End), column-major 6 x 6
  double alpha[3];  // Q4: ^N alpha^B6
  double a[3];      // Q4: ^N a^End
};

// Q1 .. Q4 fill their fields; all fills every field.
void kane_q1(const input&, output&);
void kane_q2(const input&, output&);
void kane_q3(const input&, output&);
void kane_q4(const input&, output&);
void kane_all(const input&, output&);
void kane_kept_q1(const input&, output&);  // the evaluators kept across calls, as a controller keeps them
void kane_kept_q2(const input&, output&);
void kane_kept_q3(const input&, output&);
void kane_kept_q4(const input&, output&);
void kane_kept_all(const input&, output&);
void hand_q1(const input&, output&);
void hand_q2(const input&, output&);
void hand_q3(const input&, output&);
void hand_q4(const input&, output&);
void hand_all(const input&, output&);
void kdl_q1(const input&, output&);
void kdl_q2(const input&, output&);
void kdl_q3(const input&, output&);
void kdl_q4(const input&, output&);
void kdl_all(const input&, output&);
}  // namespace arm6
