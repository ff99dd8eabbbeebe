// The rolling disc's dynamics (models/disc.hpp, 5 coordinates, 3 independent speeds):
// Kane's reduced equations for u1..u3 = ^N w^R . l_i, the contact's rates u4, u5 from
// the rolling constraints (kane::constrained_motion), integrated by RK4 with dt = 1e-3
// for 10 s from a leaning, spinning, turning start. Rolling does no work: the energy
// T + m g z stays constant (drift below 1e-8 relative), and the contact never slips.
#include <array>
#include <cmath>
#include <cstdio>

#include "models/disc.hpp"
#include "rk4.hpp"

namespace d = models::disc;
using state = kane::state_of<d::system, d::speeds5>;  // q1..q5, u1..u5, r, m, g
using rhs = kane::constrained_motion<d::system, d::rolling>;
using vector = std::array<double, rhs::size>;

int main(int argc, char** argv) {
  state s;
  s.p = {0.3, 1.2, 9.81};  // r, m, g
  rhs f(s);
  // yaw, lean, spin angle, contact x, y; then u1, u2, u3 (lean rate, spin rate, about l3)
  vector x = {0.0, 0.25, 0.0, 0.0, 0.0, 0.4, -8.0, 1.5}, k1;
  const auto energy = [&] {
    const auto& ev = f.evaluator();
    return kane::kinetic_energy<d::system>(ev) + 1.2 * 9.81 * kane::evaluate(d::height, ev);
  };
  FILE* csv = argc > 1 ? std::fopen(argv[1], "w") : nullptr;
  if (csv) std::fprintf(csv, "t,yaw,lean,spin,x,y,u1,u2,u3,E\n");
  const double dt = 1e-3;
  f(x, k1, 0.0);
  const double e0 = energy();
  double drift = 0, slip = 0;
  bool ok = f.status() == kane::solve_status::ok;
  for (int step = 0; step < 10000 && ok; ++step) {
    const double t = step * dt;
    rk4_step(f, x, t, dt);
    f(x, k1, t + dt);
    ok = f.status() == kane::solve_status::ok;
    drift = std::fmax(drift, std::abs(energy() - e0) / std::abs(e0));
    slip = std::fmax(slip, kane::express<d::N>(d::v_below, f.evaluator()).eigen().norm());
    if (csv && (step + 1) % 10 == 0)
      std::fprintf(csv, "%.3f,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.15g\n", t + dt, x[0], x[1],
                   x[2], x[3], x[4], x[5], x[6], x[7], energy());
  }
  if (csv) std::fclose(csv);
  std::printf("after 10 s: yaw %.4f, lean %.4f, contact (%.4f, %.4f)\n", x[0], x[1], x[3], x[4]);
  std::printf("energy %.10f, largest relative drift %.2e, largest contact speed %.1e\n", e0, drift, slip);
  const bool pass = ok && drift < 1e-8 && slip < 1e-12;
  std::printf(pass ? "energy conserved, no slip\n" : "FAILED\n");
  return pass ? 0 : 1;
}
