// The rolling disc and the 6-revolute arm as two C functions: compiled for a
// Cortex-M4 with arm-none-eabi-g++ -fno-exceptions -fno-rtti -Os, in float
// (KANE_EMBEDDED_SCALAR=float) or double, and run by the zero-allocation test.
#include <kane/kane.hpp>

#ifndef KANE_EMBEDDED_SCALAR
#define KANE_EMBEDDED_SCALAR double
#endif
using real = KANE_EMBEDDED_SCALAR;

namespace {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;

struct N : kane::root_frame {};
struct B1 : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B2 : kane::frame<B1, kane::simple<kane::axis::y, q<2>>> {};
struct B3 : kane::frame<B2, kane::simple<kane::axis::y, q<3>>> {};
struct B4 : kane::frame<B3, kane::simple<kane::axis::x, q<4>>> {};
struct B5 : kane::frame<B4, kane::simple<kane::axis::y, q<5>>> {};
struct B6 : kane::frame<B5, kane::simple<kane::axis::x, q<6>>> {};
struct O : kane::origin<N> {};
struct End : kane::point<O, kane::constant<3, 10>{} * e<B1, 1> + kane::constant<1, 4>{} * e<B2, 1> +
                                kane::constant<1, 5>{} * e<B3, 1> + kane::constant<3, 20>{} * e<B4, 1> +
                                kane::constant<1, 10>{} * e<B5, 1> + kane::constant<1, 20>{} * e<B6, 1>> {};

struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};
struct R : kane::frame<L, kane::simple<kane::axis::y, q<3>>> {};
struct Rad : kane::parameter<1> {};
inline constexpr Rad r;
struct Contact : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2>> {};
struct Centre : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre, -r * e<L, 3>> {};
using speeds5 = kane::angular_velocity_speeds<N, R, L, kane::dt(kane::q<4>), kane::dt(kane::q<5>)>;
inline constexpr auto v_below = kane::body_point_velocity<N, R, Centre, Below>();
using rolling =
    kane::nonholonomic<speeds5, kane::dependent<4, 5>, dot(v_below, e<N, 1>), dot(v_below, e<N, 2>)>;
}  // namespace

// Everything of the arm in N: ^N P^B6 (9), r, v, a of the end point, ^N w^B6,
// ^N alpha^B6 (3 each), the Jacobian rows of the end point (18).
extern "C" void arm_step(const real* q, const real* qd, const real* qdd, real* out) {
  kane::state<real, 6> s;
  for (int i = 0; i < 6; ++i) s.q[i] = q[i], s.qd[i] = qd[i], s.qdd[i] = qdd[i];
  kane::evaluator<kane::state<real, 6>, kane::frames<B6>> ev;
  ev.update(s);
  const auto P = kane::direction_cosines<N, B6>(s);
  for (int i = 0; i < 9; ++i) out[i] = P(i % 3, i / 3);
  const kane::vec<N, real> v[] = {kane::express<N>(kane::position<O, End>(), ev),
                                  kane::express<N>(kane::velocity<N, End>(), ev),
                                  kane::express<N>(kane::acceleration<N, End>(), ev),
                                  kane::express<N>(kane::angular_velocity<N, B6>(), ev),
                                  kane::express<N>(kane::angular_acceleration<N, B6>(), ev)};
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 3; ++i) out[9 + 3 * k + i] = v[k][i];
  const auto J = kane::partial_velocities<N>(kane::velocity<N, End>(), ev);
  for (int i = 0; i < 18; ++i) out[24 + i] = J(i % 3, i / 3);
}

// A (6) and the nonholonomic partial velocities of the disc's centre (9) and their remainder (3).
extern "C" int disc_step(const real* q, const real* u, real radius, real* out) {
  kane::state<real, 5, 5, 1> s;
  for (int i = 0; i < 5; ++i) s.q[i] = q[i], s.u[i] = u[i];
  s.p[0] = radius;
  kane::evaluator<kane::state<real, 5, 5, 1>, kane::frames<R>, kane::level::velocity, speeds5> ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<rolling>(ev);
  const auto V = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Centre>(), ev, sol);
  for (int i = 0; i < 6; ++i) out[i] = sol.A(i % 2, i / 2);
  for (int i = 0; i < 9; ++i) out[6 + i] = V(i % 3, i / 3);
  const auto t = kane::nonholonomic_remainder<N, rolling>(kane::velocity<N, Centre>(), ev, sol);
  for (int i = 0; i < 3; ++i) out[15 + i] = t(i);
  return sol.status == kane::solve_status::ok ? 0 : 1;
}
