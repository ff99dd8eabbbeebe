// Forward and inverse dynamics of the 6-revolute chain (arm6.hpp) with a mass at every link:
// link i has mass m_i at its middle (L_i / 2 along b_i x) and a full, non-diagonal
// inertia about that point in B_i; gravity -9.81 n3. Every implementation fills
// M(q), the bias h(q, q') (M q'' + h = 0 without joint torques) and q'' = -M^-1 h; the
// inverse dynamics fill tau = M q''_in + h, the joint torques that give q''_in.
#pragma once

#include <array>

#include "../../examples/models/arm6_parameters.hpp"

namespace dynamics6 {
inline constexpr const auto& L = models::arm6::length;
using models::arm6::g;
using models::arm6::inertia;
using models::arm6::mass;

struct input {
  std::array<double, 6> q, qd;
  std::array<double, 6> qdd_in;  // for the inverse dynamics
};
struct output {
  double M[36];  // column-major
  double h[6];
  double qdd[6];
  double tau[6];
  double dq[36], du[36];  // d tau or d q'' by q and q', column-major
};
// M only; M and h; all (M, h, q''); tau alone
void kane_mass(const input&, output&);
void kane_bias(const input&, output&);
void kane_forward(const input&, output&);
void kane_inverse(const input&, output&);
// the derivatives of tau (at q''_in) and of q'' by q and q': kane's analytical ones
void kane_inverse_derivatives(const input&, output&);
void kane_forward_derivatives(const input&, output&);
void hand_mass(const input&, output&);
void hand_bias(const input&, output&);
void hand_forward(const input&, output&);
void hand_inverse(const input&, output&);
void kdl_mass(const input&, output&);
void kdl_bias(const input&, output&);
void kdl_forward(const input&, output&);
void kdl_inverse(const input&, output&);
}  // namespace dynamics6
