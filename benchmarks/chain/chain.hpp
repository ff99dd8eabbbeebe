// The scaling chain: n revolute joints with axes z, y, y, x, y, x repeated,
// each about the previous body's axis, joint i+1 at 0.1 along b_i x, the end
// point at 0.1 along b_n x. All quantities in N for n = 2 .. 20.
#pragma once

#include <array>

namespace chain {
inline constexpr int max_n = 20;
struct input {
  std::array<double, max_n> q, qd, qdd;
};
struct output {
  double R[9], p[3], w[3], v[3], alpha[3], a[3];
  double J[6 * max_n];  // column-major 6 x n: w_r over v_r
};
template <int N>
void kane_all(const input&, output&);
template <int N>
void hand_all(const input&, output&);
}  // namespace chain
