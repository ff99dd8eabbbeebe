// A 3-link pendulum on a cart (models/cart_pendulum.hpp): Kane's equations as the
// right-hand side of RK4 (dt = 1e-3, 10 s) from a large swing. The energy and the
// horizontal momentum (no horizontal force) are conserved: both must stay within 1e-8.
#include <array>
#include <cmath>
#include <cstdio>

#include "models/cart_pendulum.hpp"
#include "rk4.hpp"

namespace m = models::cart_pendulum;
using rhs = kane::motion<m::system, m::evaluator>;
using vector = std::array<double, rhs::size>;

int main(int argc, char** argv) {
  m::state s;
  s[m::l] = 0.5, s[m::m] = 0.4, s[m::mc] = 1.5, s[m::g] = 9.81;
  rhs f(s);
  vector x = {0.0, 0.6, 0.9, -0.4, 0.3, 0.0, 0.5, -1.0}, k1;
  const auto energy = [&] {
    return kane::kinetic_energy<m::system>(f.evaluator()) + kane::evaluate(m::potential, f.evaluator());
  };
  const auto momentum = [&] {  // sum m v . n1
    const auto& ev = f.evaluator();
    const auto vx = [&](auto v) { return kane::express<m::N>(v, ev)[0]; };
    return s[m::mc] * vx(kane::velocity<m::N, m::Cart>()) +
           s[m::m] * (vx(kane::velocity<m::N, m::P1>()) + vx(kane::velocity<m::N, m::P2>()) +
                      vx(kane::velocity<m::N, m::P3>()));
  };
  FILE* csv = argc > 1 ? std::fopen(argv[1], "w") : nullptr;
  if (csv) std::fprintf(csv, "t,q1,q2,q3,q4,E\n");
  const double dt = 1e-3;
  f(x, k1, 0.0);
  const double e0 = energy(), p0 = momentum();
  double drift = 0, dp = 0;
  bool ok = f.status() == kane::solve_status::ok;
  for (int step = 0; step < 10000 && ok; ++step) {
    const double t = step * dt;
    rk4_step(f, x, t, dt);
    f(x, k1, t + dt);
    ok = f.status() == kane::solve_status::ok;
    drift = std::fmax(drift, std::abs(energy() - e0) / std::abs(e0));
    dp = std::fmax(dp, std::abs(momentum() - p0));
    if (csv && (step + 1) % 10 == 0)
      std::fprintf(csv, "%.3f,%.12g,%.12g,%.12g,%.12g,%.15g\n", t + dt, x[0], x[1], x[2], x[3], energy());
  }
  if (csv) std::fclose(csv);
  std::printf("after 10 s: cart %.4f, angles (%.4f, %.4f, %.4f)\n", x[0], x[1], x[2], x[3]);
  std::printf("energy %.10f: largest relative drift %.2e; momentum %.10f: largest change %.2e\n", e0, drift,
              p0, dp);
  const bool pass = ok && drift < 1e-8 && dp < 1e-8;
  std::printf(pass ? "energy and momentum conserved\n" : "FAILED\n");
  return pass ? 0 : 1;
}
