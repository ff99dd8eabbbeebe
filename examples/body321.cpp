// A rigid body oriented by a body-fixed 3-2-1 sequence (yaw q1, pitch q2,
// roll q3), with the components of its angular velocity in the body as
// generalized speeds. The kinematic differential equations are solved at each
// state; at gimbal lock (q2 = pi/2) they are singular, and kane says so.
#include <cmath>
#include <cstdio>

#include <kane/kane.hpp>

template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct B : kane::frame<N, kane::body_fixed<3, 2, 1, q<1>, q<2>, q<3>>> {};
inline constexpr auto w = kane::angular_velocity<N, B>();
using body_rates =
    kane::speeds<kane::dot(w, kane::e<B, 1>), kane::dot(w, kane::e<B, 2>), kane::dot(w, kane::e<B, 3>)>;
using state = kane::state<double, 3>;

int main() {
  state s;
  s.q = {0.4, 0.3, -0.2};
  s.u = {0.1, 0.2, 0.3};  // p, q, r: ^N w^B in B
  kane::evaluator<state, kane::frames<B>, kane::level::velocity, body_rates> ev;
  ev.update(s);
  std::printf("q' = (% .6f, % .6f, % .6f)\n", ev.coordinate_value<1, 1>(), ev.coordinate_value<2, 1>(),
              ev.coordinate_value<3, 1>());
  // Closed form: psi' = (q s_phi + r c_phi)/c_theta
  const double psi_dot = (0.2 * std::sin(-0.2) + 0.3 * std::cos(-0.2)) / std::cos(0.3);
  const bool ok = std::abs(ev.coordinate_value<1, 1>() - psi_dot) < 1e-14;

  s.q[1] = std::acos(-1.0) / 2;  // gimbal lock
  ev.update(s);
  std::printf("at q2 = pi/2: %s, q1' = %f\n",
              ev.status() == kane::solve_status::singular ? "singular" : "solved",
              ev.coordinate_value<1, 1>());
  return ok && ev.status() == kane::solve_status::singular ? 0 : 1;
}
