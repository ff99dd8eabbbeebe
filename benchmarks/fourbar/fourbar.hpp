// The four-bar linkage (examples/models/fourbar.hpp): Newton's method closes the loop from a
// guess (q2, q3) at the crank angle q1 (until max |f_k| <= 64 eps), then A of u2, u3 = A u1.
#pragma once

#include <array>

namespace fourbar {
struct input {
  std::array<double, 3> q;  // q1 and the guess for q2, q3
  std::array<double, 4> p;  // crank, coupler, rocker, ground
};
struct output {
  double q[2];  // q2, q3 closed
  double A[2];
};
void kane_solve(const input&, output&);
void hand_solve(const input&, output&);
}  // namespace fourbar
