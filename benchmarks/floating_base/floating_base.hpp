// A floating base on a free joint (Euler parameters, body rates) carrying two eight-link spatial
// arms (tests/floating_arms.hpp): 23 coordinates, 22 speeds, a thrust and two shoulder torques.
// Every implementation fills u' and, where it computes them, the derivatives of u' along the
// motion of each speed (a turn of the base in its own axes, then the coordinates) and by u, or the
// rows of u' in kane::linearize's A (by q, then u).
#pragma once

#include <array>
#include <cstddef>

namespace floating_base {
inline constexpr std::size_t nq = 23, nu = 22;
struct input {
  std::array<double, nq> q;
  std::array<double, nu> u;
};
struct output {
  double ud[nu];
  double dq[nu * nu], du[nu * nu];  // column-major
  double a[nu * (nq + nu)];         // u's rows of A, column-major
  int status;
};
void kane_forward(const input&, output&);
void kane_derivatives(const input&, output&);
// kane::linearize: by the analytical derivatives, and by jets through the whole evaluator
void kane_linearize(const input&, output&);
void jets_linearize(const input&, output&);
// kane::linearize_tangent: the base's attitude as a rotation vector; u's rows of A~ (by q~, then u)
void kane_linearize_tangent(const input&, output&);
// the derivatives by central differences of kane_forward: 4 nu calls
void central(const input&, output&);
}  // namespace floating_base
