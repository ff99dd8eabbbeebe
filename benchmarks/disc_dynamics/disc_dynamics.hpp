// The rolling disc's forward dynamics (models/disc.hpp: yaw q1, lean q2, spin q3, contact
// q4, q5; u1..u3 = ^N w^R . l_i independent, u4 = q4', u5 = q5' dependent): the right-hand
// side of an integrator, x = (q1..q5, u1..u3) -> dx/dt = (q1'..q5', u1'..u3'), as
// kane::constrained_motion returns it. The parameters are data of disc_dynamics_bench.cpp,
// so no implementation folds them into constants.
#pragma once

#include <array>

namespace disc_dynamics {
struct params {
  double r, m, g;  // p1, p2, p3 of models/disc.hpp
};
extern const params p;
struct input {
  std::array<double, 8> x;  // (q, u_ind)
};
struct output {
  double xd[8];  // (q', u_ind')
  int status;    // 0: ok (kane's status; the checked twins', ../common/checked.hpp)
};
void kane_rates(const input&, output&);          // constrained_motion, built once
void kane_reduced_rates(const input&, output&);  // A from a pose-level pass, one acceleration-level pass
void hand_rates(const input&, output&);
void hand_rates_checked(const input&, output&);
// SymPy's KanesMethod printed to C (disc_dynamics_sympy.cpp, tests/data/gen_disc_dynamics_sympy.py)
void sympy_rates(const input&, output&);
void sympy_rates_checked(const input&, output&);
}  // namespace disc_dynamics
