// The states of SymPy's cases (tests/data/sympy_dynamics.hpp) for the models of examples/models/.
#pragma once

#include <Eigen/Geometry>

#include "../examples/models/free_body.hpp"
#include "../examples/models/pendulum3d.hpp"
#include "data/sympy_dynamics.hpp"

namespace sympy_states {
// The 3D double pendulum: parameters in SymPy's order, which is the model's.
inline models::pendulum3d::state pendulum(const sympy_dynamics::pendulum_case& x) {
  models::pendulum3d::state s;
  for (int i = 0; i < 21; ++i) s.p[i] = sympy_dynamics::pendulum_p[i];
  s.q = {x.q[0], x.q[1]};
  s.u = {x.u[0], x.u[1]};
  return s;
}

// The free body: the Euler parameters of its attitude (^N P^B = dcm; the rotation that maps B's
// components to N's is its transpose); p1..p3 = a, b, c of the point P, then SymPy's m, I.., g,
// t.. (p4..p14) and f.. (p15..p17).
inline kane::state<double, 7, 6, 17> free_body(const sympy_dynamics::body_case& x) {
  kane::state<double, 7, 6, 17> s;
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> c(x.dcm);
  const Eigen::Quaterniond e(Eigen::Matrix3d(c.transpose()));
  s.q = {e.w(), e.x(), e.y(), e.z(), x.q[3], x.q[4], x.q[5]};
  for (int i = 0; i < 6; ++i) s.u[i] = x.u[i];
  const auto& bp = sympy_dynamics::body_p;
  for (int i = 0; i < 17; ++i) s.p[i] = i < 3 ? bp[11 + i] : i < 14 ? bp[i - 3] : bp[i];
  return s;
}
}  // namespace sympy_states
