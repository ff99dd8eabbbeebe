// Kane's generalized forces as expressions (dynamics/generalized_forces.hpp): their numbers
// at a state against the one-pass M and f (F_r + F*_r = f_r - (M u')_r) for the 3D double
// pendulum with bodies, a particle, torques and a force; their printed form for a pendulum.
#include <catch2/catch.hpp>
#include <string>

#include <kane/dynamics/generalized_forces.hpp>
#include <kane/print.hpp>

#include "../examples/models/pendulum3d.hpp"

namespace {
namespace pd = models::pendulum3d;
using sp = kane::qdot_speeds<2>;
using kane::e;
struct m_ : kane::parameter<1> {};
struct g_ : kane::parameter<2> {};
struct L_ : kane::parameter<3> {};
constexpr m_ m;
constexpr g_ g;
constexpr L_ L;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::x, kane::coordinate<1>>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, -L * e<A, 3>> {};
using pendulum = kane::system<kane::particle<P, m>, kane::gravity<-g * e<N, 3>>>;
}  // namespace

TEST_CASE("generalized forces: F_r + F*_r = f_r - (M u')_r for the 3D double pendulum") {
  pd::state s;
  s.q = {0.3, -0.5};
  s.u = {0.7, 0.2};
  s.ud = {-1.1, 2.3};
  s.p = {1,    0.8,  2,    1.5,   0.5,    0.1,   0.12, 0.03, 0.01, 0.02, -0.01,
         0.09, 0.08, 0.02, 0.005, -0.004, 0.003, 9.81, 3,    0.4,  0.2};
  pd::evaluator ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<pd::system>(ev);
  const Eigen::Vector2d expected = eom.f - eom.M * Eigen::Vector2d(s.ud[0], s.ud[1]);
  const double f1 = kane::evaluate(kane::generalized_active_force<pd::N, pd::system, sp, 1>(), ev);
  const double f2 = kane::evaluate(kane::generalized_active_force<pd::N, pd::system, sp, 2>(), ev);
  const double s1 = kane::evaluate(kane::generalized_inertia_force<pd::N, pd::system, sp, 1>(), ev);
  const double s2 = kane::evaluate(kane::generalized_inertia_force<pd::N, pd::system, sp, 2>(), ev);
  CHECK(f1 + s1 == Approx(expected(0)).epsilon(1e-13));
  CHECK(f2 + s2 == Approx(expected(1)).epsilon(1e-13));
}

TEST_CASE("generalized forces: a pendulum's F_1 and F*_1 print in Kane's notation") {
  const auto active = kane::generalized_active_force<N, pendulum, kane::qdot_speeds<1>, 1>();
  const auto inertia = kane::generalized_inertia_force<N, pendulum, kane::qdot_speeds<1>, 1>();
  // v_1 = a1 x (-L a3) = -L (-a2); F_1 = v_1 . m g, F*_1 = -m a . v_1
  CHECK(kane::to_string(active) == "(-L_ -a2) . (m_ (-g_ n3))");
  CHECK(kane::to_string(inertia) == "-m_*(^N alpha^A x (-L_ a3) + ^N w^A x (^N w^A x (-L_ a3))) . (-L_ -a2)");
}
