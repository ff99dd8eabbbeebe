// A pendulum from frames to its motion: the rod turns about n3 by q1 (frame A), the bob P of
// mass m hangs at -L a2 from the pivot O, gravity is -g n2. kane::motion is x' = (q', u') for any
// integrator; here RK4 with steps of 1 ms for 2 s, which keeps the energy T + V.
#include <array>
#include <cmath>
#include <cstdio>

#include <kane/kane.hpp>

#include "rk4.hpp"

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct L : kane::parameter<1> {};  // rod length
struct m : kane::parameter<2> {};  // bob mass
struct g : kane::parameter<3> {};  // gravity
struct O : kane::origin<N> {};
struct P : kane::point<O, -L{} * kane::e<A, 2>> {};
using pendulum = kane::system<kane::particle<P, m{}>, kane::gravity<-g{} * kane::e<N, 2>>>;
using state = kane::state_of<pendulum>;  // q1, u1 = q1', three parameters

int main() {
  state s;
  s[L{}] = 0.8, s[m{}] = 1.5, s[g{}] = 9.81;
  kane::motion<pendulum> f(s);
  std::array<double, 2> x = {1.0, 0.0}, dx;  // q1 = 1 rad, at rest
  f(x, dx, 0.0);
  std::printf("u1' = %.6f (closed form -g/L sin q1 = %.6f)\n", dx[1], -9.81 / 0.8 * std::sin(1.0));
  const auto energy = [&] {
    return kane::kinetic_energy<pendulum>(f.evaluator()) + kane::potential_energy<pendulum>(f.evaluator());
  };
  const double e0 = energy();
  std::printf("T + V = %.6f\n", e0);
  for (int k = 0; k < 2000; ++k) rk4_step(f, x, 1e-3 * k, 1e-3);
  f(x, dx, 2.0);
  std::printf("after 2 s: q1 = %.6f, u1 = %.6f, T + V = %.6f\n", x[0], x[1], energy());
  return f.status() == kane::solve_status::ok && std::abs(energy() - e0) < 1e-9 ? 0 : 1;
}
