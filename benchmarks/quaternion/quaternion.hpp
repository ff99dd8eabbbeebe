// A free body with Euler parameters (examples/models/free_body.hpp): from q (the attitude
// as a unit quaternion, the mass centre) and the speeds u (body rates, centre velocity),
// the kinematic equations q' = W(q) u and ^N v^P of the point P = Bo + a b1 + b b2 + c b3.
#pragma once

#include <array>

namespace quaternion {
struct input {
  std::array<double, 7> q;
  std::array<double, 6> u;
  std::array<double, 3> p;  // a, b, c
};
struct output {
  double qd[7];
  double v[3];  // ^N v^P in N
};
void kane_rates(const input&, output&);
void hand_rates(const input&, output&);
}  // namespace quaternion
