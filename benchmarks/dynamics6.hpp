// Forward and inverse dynamics of the 6-revolute chain (arm6.hpp) with a mass at every link:
// link i has mass m_i at its middle (L_i / 2 along b_i x) and a full, non-diagonal
// inertia about that point in B_i; gravity -9.81 n3. Every implementation fills
// M(q), the bias h(q, q') (M q'' + h = 0 without joint torques) and q'' = -M^-1 h; the
// inverse dynamics fill tau = M q''_in + h, the joint torques that give q''_in.
#pragma once

#include <array>

namespace dynamics6 {
inline constexpr double L[6] = {0.3, 0.25, 0.2, 0.15, 0.1, 0.05};
inline constexpr double mass[6] = {2.0, 1.6, 1.2, 0.8, 0.5, 0.3};
// I11, I22, I33, I12, I23, I31 of link i about its mass centre, in B_i
inline constexpr double inertia[6][6] = {
    {0.020, 0.030, 0.025, 0.002, -0.001, 0.0015},     {0.015, 0.022, 0.018, -0.0012, 0.0008, 0.001},
    {0.010, 0.014, 0.012, 0.0009, -0.0006, -0.0007},  {0.006, 0.008, 0.007, -0.0005, 0.0004, 0.0003},
    {0.003, 0.004, 0.0035, 0.0002, -0.0002, 0.00025}, {0.0015, 0.002, 0.0018, -0.0001, 0.0001, 0.00012}};
inline constexpr double g = 9.81;

struct input {
  std::array<double, 6> q, qd;
  std::array<double, 6> qdd_in;  // for the inverse dynamics
};
struct output {
  double M[36];  // column-major
  double h[6];
  double qdd[6];
  double tau[6];
};
// M only; M and h; all (M, h, q''); tau alone
void kane_mass(const input&, output&);
void kane_bias(const input&, output&);
void kane_forward(const input&, output&);
void kane_inverse(const input&, output&);
void hand_mass(const input&, output&);
void hand_bias(const input&, output&);
void hand_forward(const input&, output&);
void hand_inverse(const input&, output&);
void kdl_mass(const input&, output&);
void kdl_bias(const input&, output&);
void kdl_forward(const input&, output&);
void kdl_inverse(const input&, output&);
}  // namespace dynamics6
