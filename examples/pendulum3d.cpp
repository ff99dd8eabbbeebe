// The 3D double pendulum of models/pendulum3d.hpp (rigid links with full inertia,
// a tip mass, a torsion spring) without damping: Kane's equations M u' = f as the
// right-hand side of a hand-written RK4 (kane::motion), dt = 1e-3 for 10 s. The
// energy T + V is conserved: its drift must stay below 1e-8 relative.
// With an argument, the trajectory t, q1, q2, u1, u2, E is written to that CSV file.
#include <array>
#include <cmath>
#include <cstdio>

#include "models/pendulum3d.hpp"
#include "rk4.hpp"

namespace m = models::pendulum3d;
using rhs = kane::motion<m::system, kane::qdot_speeds<2>>;  // the system's own evaluator, u = q'
using vector = std::array<double, rhs::size>;

// T + V: V of gravity (zero at the pivot's height), and the spring's k q2^2 / 2
double energy(const rhs& f) {
  const auto& ev = f.evaluator();
  const double q2 = ev.state()[kane::q<2>];
  return kane::kinetic_energy<m::system>(ev) + kane::potential_energy<m::system>(ev) +
         ev.state()[m::k] * q2 * q2 / 2;
}

int main(int argc, char** argv) {
  m::state s;
  s[m::lA] = 1.5, s[m::lB] = 1.4, s[m::mA] = 0.9, s[m::mB] = 1.0, s[m::mQ] = 1.2;
  s[m::IA1] = 0.7, s[m::IA2] = 0.8, s[m::IA3] = 0.9, s[m::IA12] = 0.07, s[m::IA23] = -0.06, s[m::IA31] = 0.07;
  s[m::IB1] = 0.66, s[m::IB2] = 1.2, s[m::IB3] = 1.0, s[m::IB12] = 0.02, s[m::IB23] = -0.03,
  s[m::IB31] = -0.03;
  s[m::g] = 9.81, s[m::k] = 1.5, s[m::c] = 0, s[m::d] = 0;  // no damper, no drag
  rhs f(s);
  vector x = {1.2, -0.7, 0.5, 2.0}, k1;
  FILE* csv = argc > 1 ? std::fopen(argv[1], "w") : nullptr;
  if (csv) std::fprintf(csv, "t,q1,q2,u1,u2,E\n");
  const double dt = 1e-3;
  f(x, k1, 0.0);
  const double e0 = energy(f);
  double drift = 0;
  bool ok = f.status() == kane::solve_status::ok;
  for (int step = 0; step < 10000 && ok; ++step) {
    const double t = step * dt;
    rk4_step(f, x, t, dt);
    f(x, k1, t + dt);  // the evaluator at the new state
    ok = f.status() == kane::solve_status::ok;
    const double e = energy(f);
    drift = std::fmax(drift, std::abs(e - e0) / std::abs(e0));
    if (csv && (step + 1) % 10 == 0)
      std::fprintf(csv, "%.3f,%.12g,%.12g,%.12g,%.12g,%.15g\n", t + dt, x[0], x[1], x[2], x[3], e);
  }
  if (csv) std::fclose(csv);
  std::printf("after 10 s: q = (%.6f, %.6f), u = (%.6f, %.6f)\n", x[0], x[1], x[2], x[3]);
  std::printf("energy %.12f, largest relative drift %.2e\n", e0, drift);
  const bool pass = ok && drift < 1e-8;
  std::printf(pass ? "energy conserved\n" : "FAILED\n");
  return pass ? 0 : 1;
}
