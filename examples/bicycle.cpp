// The kinematics of the Whipple bicycle (models/bicycle.hpp) with the geometry of the
// benchmark of Meijaard, Papadopoulos, Ruina and Schwab (2007), Table 1: wheelbase
// w = 1.02, trail c = 0.08, steer axis tilt pi/10, wheel radii 0.3 and 0.35. For roll
// and steer angles the pitch closes the front contact (Newton), and the rolling
// constraints give the yaw rate. Checked: upright and straight, the pitch is 0; near
// it, the yaw rate is the benchmark's linear kinematics psi' = (v delta + c delta')
// cos(lambda) / w (Meijaard et al. 2007, section 3), here with the sign of kane's
// (SymPy's) steer axis, which points down.
#include <cmath>
#include <cstdio>

#include "models/bicycle.hpp"

namespace {
using namespace models::bicycle;

// The benchmark's geometry in the model's parameters (as SymPy's test_bicycle converts it).
state benchmark() {
  const double rR = 0.3, rF = 0.35, wb = 1.02, trail = 0.08, hta = M_PI / 2 - M_PI / 10;
  const double rake = -(trail * std::sin(hta) - rF * std::cos(hta));
  state s;
  s.p = {rF,
         rR,
         hta,
         rake,
         wb * std::cos(hta) - (rF - rR) * std::sin(hta),
         wb * std::sin(hta) - (rake - (rF - rR) * std::cos(hta))};
  return s;
}

// The yaw rate for roll, steer, the steer rate and the rear wheel rate, and the pitch.
struct motion {
  double pitch, yaw_rate;
  kane::solve_status status;
  std::size_t steps;
};
motion move(double roll, double steer, double steer_rate, double wheel_rate) {
  state s = benchmark();
  s.q = {0, 0, 0, roll, 0, steer};
  evaluator ev;
  const auto closed = kane::solve_configuration<pitch>(ev, s);
  const auto sol = kane::solve_constraints<rolling>(ev);
  const Eigen::Vector3d independent(0, steer_rate, wheel_rate);  // u4, u6, u7
  const kane::solve_status st = closed.status != kane::solve_status::ok ? closed.status : sol.status;
  return {s.q[4], (sol.A * independent)(2), st, closed.iterations};
}
}  // namespace

int main() {
  const double v = 5, rR = 0.3, wb = 1.02, trail = 0.08, lambda = M_PI / 10;
  int failures = 0;
  std::printf("  roll    steer     pitch     yaw rate at v = 5 m/s   Newton steps\n");
  for (double roll : {-0.4, 0.0, 0.4})
    for (double steer : {-0.6, -0.2, 0.0, 0.2, 0.6}) {
      const motion m = move(roll, steer, 0, v / rR);
      failures += m.status != kane::solve_status::ok;
      std::printf("% 6.2f  % 6.2f  % 9.6f  % 12.6f           %zu\n", roll, steer, m.pitch, m.yaw_rate,
                  m.steps);
    }
  const motion straight = move(0, 0, 0, v / rR);
  const double delta = 1e-6, kv = move(0, delta, 0, v / rR).yaw_rate / delta, kc = move(0, 0, 1, 0).yaw_rate;
  const double kv_paper = -v * std::cos(lambda) / wb, kc_paper = -trail * std::cos(lambda) / wb;
  std::printf("upright and straight: pitch %.1e\n", straight.pitch);
  std::printf("d(yaw rate)/d(steer)      %.10f, benchmark -v cos(lambda)/w %.10f\n", kv, kv_paper);
  std::printf("d(yaw rate)/d(steer rate) %.10f, benchmark -c cos(lambda)/w %.10f\n", kc, kc_paper);
  failures += std::abs(straight.pitch) > 1e-12;
  failures += std::abs(kv - kv_paper) > 1e-5 * std::abs(kv_paper);
  failures += std::abs(kc - kc_paper) > 1e-12;
  std::printf(
      failures ? "FAILED: %d checks\n" : "pitch closes the loop; yaw rates agree with the benchmark\n",
      failures);
  return failures ? 1 : 0;
}
