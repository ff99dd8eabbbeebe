// A 6-revolute arm (models/arm6.hpp): pose, velocity and acceleration of the
// end point and of the last body.
#include <cstdio>

#include "models/arm6.hpp"

using namespace models::arm6;

template <class F>
void show(const char* what, const kane::vec<F>& v) {
  std::printf("%-10s (% .6f, % .6f, % .6f)\n", what, v[0], v[1], v[2]);
}

int main() {
  kane::state<double, 6> s;
  s.q = {0.1, -0.4, 0.8, 0.3, -1.2, 0.6};
  s.qd = {0.5, 0.2, -0.3, 1.0, 0.4, -0.7};
  s.qdd = {0.1, -0.2, 0.3, -0.1, 0.2, 0.05};

  constexpr auto r = kane::position<O, End>();
  constexpr auto v = kane::velocity<N, End>();
  constexpr auto a = kane::acceleration<N, End>();
  constexpr auto w = kane::angular_velocity<N, B6>();
  constexpr auto alpha = kane::angular_acceleration<N, B6>();
  constexpr auto v_two_point = kane::two_point_velocity<N, B6, J6, End>();
  // the values of these reads: one outward pass over B1 .. B5 (B6 is one edge below B5 and
  // e_B6,1 = e_B5,1) at the acceleration level, then each read in N
  kane::evaluator_for<decltype(s),
                      kane::reads<r, v, a, w, alpha, kane::partials_of(w), kane::partials_of(v), v_two_point>>
      ev;
  ev.update(s);

  const auto NPB6 = kane::direction_cosines<N, B6>(s);
  std::printf("^N P^B6 row 1  (% .6f, % .6f, % .6f)\n", NPB6(0, 0), NPB6(0, 1), NPB6(0, 2));
  show("r^O/End", kane::express<N>(r, ev));
  show("^N v^End", kane::express<N>(v, ev));
  show("^N a^End", kane::express<N>(a, ev));
  show("^N w^B6", kane::express<N>(w, ev));
  show("^N al^B6", kane::express<N>(alpha, ev));
  // The 6x6 geometric Jacobian: partial angular velocities of B6 over partial
  // velocities of the end point, u = q'.
  Eigen::Matrix<double, 6, 6> J;
  J << kane::partial_velocities<N>(w, ev), kane::partial_velocities<N>(v, ev);
  std::printf("J row 4  ");
  for (int j = 0; j < 6; ++j) std::printf(" % .4f", J(3, j));
  std::printf("\n");
  const Eigen::Matrix<double, 6, 1> u = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(s.qd.data());
  const bool jacobian_ok = (J.bottomRows<3>() * u - kane::express<N>(v, ev).eigen()).norm() < 1e-14;
  // The end point is fixed in B6: the two-point theorem from J6 gives the same velocity.
  const auto v2pt = kane::express<N>(v_two_point, ev);
  return jacobian_ok && kane::is_approx(v2pt, kane::express<N>(v, ev), 1e-14) ? 0 : 1;
}
