// G(e) of Euler parameters e = (e0, e1, e2, e3), scalar first: a turn by a rotation vector dtheta in
// the frame's own axes, e (1, dtheta / 2) (a product of quaternions), moves e by de = G(e) dtheta.
#pragma once

#include <Eigen/Core>

namespace kane::detail {

// G(e) = 1/2 [-e1 -e2 -e3; e0 -e3 e2; e3 e0 -e1; -e2 e1 e0]
template <class S>
Eigen::Matrix<S, 4, 3> attitude_map(S e0, S e1, S e2, S e3) {
  Eigen::Matrix<S, 4, 3> g;
  g << -e1, -e2, -e3, e0, -e3, e2, e3, e0, -e1, -e2, e1, e0;
  return S(0.5) * g;
}

}  // namespace kane::detail
