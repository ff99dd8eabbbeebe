// Four small models, the right-hand side x -> dx/dt = (q', u') of each, every parameter
// a compile-time constant in every implementation (kane, hand-written closed forms, and
// SymPy's KanesMethod printed to C with cse by tests/data/gen_small_sympy.py):
//
// top: a heavy symmetric top on a fixed point O. Frames A = N turned about n3 by q1,
//   B = A about a1 by q2, C = B about b3 by q3 (3-1-3). Speeds u_i = ^N w^C . c_i.
//   Mass m = 1.5 at Co = O + l c3, l = 0.3; inertia about Co in C diag(0.02, 0.02, 0.035);
//   gravity -9.81 n3. x = (q1, q2, q3, u1, u2, u3).
// spacecraft: a free body B, Euler parameters q1..q4 (scalar first) of B in N, mass centre
//   Bo = O + q5 n1 + q6 n2 + q7 n3; speeds u1..u3 = ^N w^B . b_i, u4..u6 = q5', q6', q7';
//   a reaction wheel W spinning about b3 at the free speed u7 = ^B w^W . b3, its centre at Bo.
//   B: mass 10, inertia about Bo in B diag(1.2, 1.5, 1.9); W: mass 0.5, inertia about Bo in W
//   diag(0.01, 0.01, 0.02) (the same in B: W turns about its symmetry axis). No load. x = (q1..q7, u1..u7).
// pendulum: a planar double pendulum of point masses. A = N turned about n3 by q1, B = A about
//   a3 by q2; P1 = O + 1.2 a1 (mass 1.0), P2 = P1 + 0.8 b1 (mass 0.7); gravity 9.81 n1.
//   u_i = q_i'. x = (q1, q2, u1, u2).
// pendulum_absolute: the same pendulum on absolute angles, B = N turned about n3 by q2, as a
//   textbook and SymPy write it. x = (q1, q2, u1, u2).
// Each hand and SymPy function has a checked twin (F_checked, ../common/checked.hpp): every input
// and output tested finite, else NaN and status 1. kane's status is that of kane::motion.
#pragma once

#include <array>

namespace small {
template <int N>
struct input {
  std::array<double, N> x;
};
template <int N>
struct output {
  double xd[N];
  int status;  // 0: ok
};
using top_in = input<6>;
using top_out = output<6>;
using spacecraft_in = input<14>;
using spacecraft_out = output<14>;
using pendulum_in = input<4>;
using pendulum_out = output<4>;

void top_kane(const top_in&, top_out&);
void top_hand(const top_in&, top_out&);
void top_sympy(const top_in&, top_out&);
void top_hand_checked(const top_in&, top_out&);
void top_sympy_checked(const top_in&, top_out&);
void spacecraft_kane(const spacecraft_in&, spacecraft_out&);
void spacecraft_hand(const spacecraft_in&, spacecraft_out&);
void spacecraft_sympy(const spacecraft_in&, spacecraft_out&);
void spacecraft_hand_checked(const spacecraft_in&, spacecraft_out&);
void spacecraft_sympy_checked(const spacecraft_in&, spacecraft_out&);
void pendulum_kane(const pendulum_in&, pendulum_out&);
void pendulum_hand(const pendulum_in&, pendulum_out&);
void pendulum_sympy(const pendulum_in&, pendulum_out&);
void pendulum_hand_checked(const pendulum_in&, pendulum_out&);
void pendulum_sympy_checked(const pendulum_in&, pendulum_out&);
void pendulum_absolute_kane(const pendulum_in&, pendulum_out&);
void pendulum_absolute_hand(const pendulum_in&, pendulum_out&);
void pendulum_absolute_sympy(const pendulum_in&, pendulum_out&);
void pendulum_absolute_hand_checked(const pendulum_in&, pendulum_out&);
void pendulum_absolute_sympy_checked(const pendulum_in&, pendulum_out&);
}  // namespace small
