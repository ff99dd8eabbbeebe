// Every call of docs/reference.md on one small model: a double pendulum of two rigid links, a
// torque input at its joint. Each result's fields are read by name; the program fails unless every
// status is ok and the equations agree with one another.
#include <array>
#include <cmath>
#include <cstdio>

#include <kane/kane.hpp>

namespace dp {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
inline constexpr kane::named_parameter<1, "L"> L;  // link length
inline constexpr kane::named_parameter<2, "m"> m;  // link mass
inline constexpr kane::named_parameter<3, "g"> g;  // gravity
inline constexpr kane::named_input<1, "T"> T;      // joint torque

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::z, q<2>>> {};
struct O : kane::origin<N> {};
struct Ao : kane::point<O, kane::constant<1, 2>{} * L * e<A, 1>> {};
struct J : kane::point<O, L * e<A, 1>> {};  // the joint
struct Bo : kane::point<J, kane::constant<1, 2>{} * L * e<B, 1>> {};

inline constexpr auto rod = kane::constant<1, 12>{} * m * L * L;  // about an axis across a rod
using links =
    kane::system<kane::rigid_body<A, Ao, m, kane::inertia<A, Ao, 0, rod, rod>>,
                 kane::rigid_body<B, Bo, m, kane::inertia<B, Bo, 0, rod, rod>>, kane::gravity<g * e<N, 1>>,
                 kane::torque<B, T * e<N, 3>>, kane::torque<A, -T * e<N, 3>>>;
using state = kane::state_of<links>;              // kane::state<double, 2, 2, 3, 1>: nq, nu, np, nr
using evaluator = kane::system_evaluator<links>;  // the frames the items read, level::acceleration
}  // namespace dp

int main() {
  using namespace dp;
  bool ok = true;
  const auto expect = [&](bool x, const char* what) {
    if (!x) std::printf("failed: %s\n", what);
    ok = ok && x;
  };

  // The state: q, qd, qdd, u, ud, p, r, t, also by name.
  state s;
  s.q = {0.4, 0.9};
  s.u = {1.1, -0.3};
  s[m] = 1.5, s[L] = 0.8, s[g] = 9.81;
  s[T] = 0.2;

  // An evaluator: update, then status.
  evaluator ev;
  ev.update(s);
  expect(ev.status() == kane::solve_status::ok, "evaluator status");

  // Vectors and direction cosines: components by index.
  const kane::vec<N> v = kane::express<N>(kane::velocity<N, Bo>(), ev);
  const kane::dcm<N, B> P = kane::direction_cosines<N, B>(s);
  expect(std::fabs(P(0, 0) - std::cos(1.3)) < 1e-15 && v[2] == 0.0, "vec and dcm");

  // M u' = f: fields M, f, status.
  const auto eom = kane::mass_matrix_and_forcing<links>(ev);
  const auto [ud, solved] = kane::speed_derivatives(eom);
  expect(eom.status == kane::solve_status::ok && solved == kane::solve_status::ok, "equations");

  // Inverse and forward dynamics: {tau, status}, {ud, status}.
  const auto [ud2, forward_status] = kane::forward_dynamics<links>(ev);
  expect(forward_status == kane::solve_status::ok && (ud2 - ud).norm() < 1e-12, "forward dynamics");
  s.ud = {ud(0), ud(1)};
  ev.update(s);
  const auto [tau, inverse_status] = kane::inverse_dynamics<links>(ev);
  expect(inverse_status == kane::solve_status::ok && tau.norm() < 1e-12, "inverse dynamics");

  // The pin's reaction on link B (the torque T is applied, not a reaction): force, moment about J, status.
  const auto pin = kane::reaction<links, kane::cut<J, B>>(ev);
  expect(pin.status == kane::solve_status::ok && std::fabs(pin.moment[2]) < 1e-12, "reaction");  // a free pin

  // Energies and momenta.
  const double energy = kane::kinetic_energy<links>(ev) + kane::potential_energy<links>(ev);
  expect(std::isfinite(energy), "energy");

  // x' = f(x, t) for an integrator: x = (q, u), entries by name.
  kane::motion<links> rhs(s);
  std::array<double, 4> x{s.q[0], s.q[1], s.u[0], s.u[1]}, dx{};
  rhs.inputs() = {0.2};
  rhs(x, dx, 0.0);
  expect(rhs.status() == kane::solve_status::ok && std::fabs(dx[rhs.index(kane::u<2>)] - ud(1)) < 1e-12,
         "motion");
  const auto at_x = rhs.evaluator(x, 0.0);  // the evaluator at x, u' = 0

  // The linearization: A, B, rate, status; rows and columns by name.
  const auto lin = kane::linearize<links, evaluator, kane::inputs<T>>(s);
  expect(lin.status == kane::solve_status::ok && at_x.status() == kane::solve_status::ok, "linearize");
  const double dud_dT = lin.B(lin.index(kane::u<2>), 0);

  std::printf("u' = (%.6f, %.6f), joint moment %.3f, du2'/dT %.6f\n", ud(0), ud(1), pin.moment[2], dud_dT);
  return ok ? 0 : 1;
}
