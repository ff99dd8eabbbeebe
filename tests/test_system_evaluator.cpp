// The system's own state and evaluator (dynamics/system_evaluator.hpp): the sizes counted from the
// items against the models' own counts, and kane::motion<System> against closed forms, SymPy's
// KanesMethod and the same model with an evaluator written by hand.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "../examples/models/arm6_dynamics.hpp"
#include "../examples/models/bicycle.hpp"
#include "../examples/models/disc.hpp"
#include "../examples/models/gyrostat.hpp"
#include "../examples/models/heavy_top.hpp"
#include "data/sympy_bicycle_dynamics.hpp"
#include "data/sympy_disc_dynamics.hpp"

namespace {
using kane::e;
// The pendulum of the README: L at p1, m at p2, g at p3; a torque r2 n3 on A.
namespace pend {
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct L : kane::parameter<1> {};
struct m : kane::parameter<2> {};
struct g : kane::parameter<3> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, -L{} * e<A, 2>> {};
using system = kane::system<kane::particle<P, m{}>, kane::gravity<-g{} * e<N, 2>>,
                            kane::torque<A, kane::r<2> * e<N, 3>>>;
}  // namespace pend
// A planar double pendulum on absolute angles: A and B both turned from N.
namespace absolute {
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct B : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<2>>> {};
struct l1 : kane::parameter<1> {};
struct l2 : kane::parameter<2> {};
struct m1 : kane::parameter<3> {};
struct m2 : kane::parameter<4> {};
struct g : kane::parameter<5> {};
struct O : kane::origin<N> {};
struct P1 : kane::point<O, l1{} * e<A, 1>> {};
struct P2 : kane::point<P1, l2{} * e<B, 1>> {};
using system = kane::system<kane::particle<P1, m1{}>, kane::particle<P2, m2{}>, kane::gravity<g{} * e<N, 1>>>;
}  // namespace absolute

template <class M, std::size_t N>
std::array<double, N> rate(M& f, const std::array<double, N>& x) {
  std::array<double, N> dx{};
  f(x, dx, 0.0);
  return dx;
}
}  // namespace

TEST_CASE("system evaluator: the state's sizes are the models' counts") {
  STATIC_REQUIRE(std::is_same_v<kane::state_of<pend::system>, kane::state<double, 1, 1, 3, 2>>);
  STATIC_REQUIRE(std::is_same_v<kane::state_of<absolute::system, void, float>, kane::state<float, 2, 2, 5>>);
  namespace t = models::heavy_top;
  STATIC_REQUIRE(std::is_same_v<kane::state_of<t::system, t::speeds>, t::state>);
  namespace gy = models::gyrostat;
  STATIC_REQUIRE(std::is_same_v<kane::state_of<gy::system, gy::speeds>, gy::state>);
  namespace a = models::arm6;
  STATIC_REQUIRE(std::is_same_v<kane::state_of<a::driven>, kane::state<double, 6, 6, 0, 6>>);
  namespace d = models::disc;
  STATIC_REQUIRE(std::is_same_v<kane::state_of<d::system, d::speeds5>, kane::state<double, 5, 5, 3>>);
  namespace b = models::bicycle;
  STATIC_REQUIRE(std::is_same_v<kane::state_of<b::system, b::speeds>, b::dynamics_state>);
  // the frames the items read: those the models' evaluators hold, and their ancestors
  STATIC_REQUIRE(
      std::is_same_v<kane::system_evaluator<t::system, t::speeds>::closure, t::evaluator::closure>);
  STATIC_REQUIRE(
      std::is_same_v<kane::system_evaluator<gy::system, gy::speeds>::closure, gy::evaluator::closure>);
}

TEST_CASE("system evaluator: kane::motion<System> of the pendulum against its closed form") {
  kane::state_of<pend::system> s;
  s[pend::L{}] = 0.8, s[pend::m{}] = 1.5, s[pend::g{}] = 9.81;
  kane::motion<pend::system> f(s);
  f.inputs()[1] = 0.6;  // r2: a torque 0.6 n3
  const std::array<double, 2> x{1.0, -0.4};
  const auto dx = rate(f, x);
  REQUIRE(f.status() == kane::solve_status::ok);
  CHECK(dx[0] == -0.4);
  CHECK(dx[1] == Approx(-9.81 / 0.8 * std::sin(1.0) + 0.6 / (1.5 * 0.8 * 0.8)).epsilon(1e-14));
}

TEST_CASE(
    "system evaluator: kane::motion<System> of the absolute-angle double pendulum against its closed form") {
  kane::state_of<absolute::system> s;
  const double l1 = 1.2, l2 = 0.8, m1 = 1.0, m2 = 0.7, g = 9.81;
  s.p = {l1, l2, m1, m2, g};
  kane::motion<absolute::system> f(s);
  for (const auto& x :
       {std::array<double, 4>{0.3, -0.7, 1.1, -0.4}, std::array<double, 4>{2.0, 0.5, -0.3, 2.2}}) {
    const auto dx = rate(f, x);
    REQUIRE(f.status() == kane::solve_status::ok);
    // M [q1'', q2''] = f, gravity g n1, angles from n1
    const double c = std::cos(x[0] - x[1]), sn = std::sin(x[0] - x[1]);
    Eigen::Matrix2d M;
    M << (m1 + m2) * l1 * l1, m2 * l1 * l2 * c, m2 * l1 * l2 * c, m2 * l2 * l2;
    const Eigen::Vector2d rhs(-m2 * l1 * l2 * sn * x[3] * x[3] - (m1 + m2) * g * l1 * std::sin(x[0]),
                              m2 * l1 * l2 * sn * x[2] * x[2] - m2 * g * l2 * std::sin(x[1]));
    const Eigen::Vector2d qdd = M.lu().solve(rhs);
    CHECK(dx[0] == x[2]);
    CHECK(dx[1] == x[3]);
    CHECK(dx[2] == Approx(qdd(0)).epsilon(1e-13));
    CHECK(dx[3] == Approx(qdd(1)).epsilon(1e-13));
  }
}

TEST_CASE("system evaluator: kane::motion<System, Speeds> equals the form with an evaluator written") {
  namespace t = models::heavy_top;
  kane::motion<t::system, t::speeds> top(t::state{});
  kane::motion<t::system, t::evaluator> top_written(t::state{});
  const std::array<double, 6> xt{0.1, 0.5, 0.3, 1.0, -2.0, 3.0};
  CHECK(rate(top, xt) == rate(top_written, xt));
  namespace gy = models::gyrostat;
  kane::motion<gy::system, gy::speeds> craft(gy::state{});
  kane::motion<gy::system, gy::evaluator> craft_written(gy::state{});
  const std::array<double, 14> xg{0.5, 0.5, -0.5, 0.5, 1, 2, 3, 0.1, -0.2, 0.3, 0.4, 0.5, 0.6, 3.0};
  CHECK(rate(craft, xg) == rate(craft_written, xg));
  namespace a = models::arm6;
  using arm_state = kane::state<double, 6, 6, 0, 6>;
  kane::motion<a::driven> arm(arm_state{});
  kane::motion<a::driven, kane::evaluator<arm_state, kane::frames<a::B6>>> arm_written(arm_state{});
  arm.inputs() = arm_written.inputs() = {1.0, -2.0, 0.5, 0.3, -0.1, 0.2};
  const std::array<double, 12> xa{0.1, -0.4, 0.9, 0.2, -1.1, 0.5, 0.3, 0.2, -0.1, 0.4, 0.6, -0.5};
  CHECK(rate(arm, xa) == rate(arm_written, xa));
}

TEST_CASE(
    "system evaluator: kane::constrained_motion<System, NH> of the disc and the bicycle against SymPy") {
  namespace d = models::disc;
  kane::state_of<d::system, d::speeds5> sd;
  for (std::size_t i = 0; i < 3; ++i) sd.p[i] = sympy_disc_dynamics::p[i];
  kane::constrained_motion<d::system, d::rolling> disc(sd);
  for (const auto& c : sympy_disc_dynamics::disc) {
    const std::array<double, 8> x{c.q[0], c.q[1], c.q[2], c.q[3], c.q[4], c.u[0], c.u[1], c.u[2]};
    const auto dx = rate(disc, x);
    REQUIRE(disc.status() == kane::solve_status::ok);
    for (std::size_t i = 0; i < 3; ++i) CHECK(dx[5 + i] == Approx(c.ud[i]).epsilon(1e-12).margin(1e-13));
  }
  namespace b = models::bicycle;
  kane::state_of<b::system, b::speeds> sb;
  for (std::size_t i = 0; i < 27; ++i) sb.p[i] = sympy_bicycle_dynamics::p[i];
  kane::constrained_motion<b::system, b::rolling> bike(sb);
  for (const auto& c : sympy_bicycle_dynamics::cases) {
    const std::array<double, 9> x{c.q[0], c.q[1], c.q[2], c.q[3], c.q[4], c.q[5], c.u[3], c.u[5], c.u[6]};
    const auto dx = rate(bike, x);
    REQUIRE(bike.status() == kane::solve_status::ok);
    const std::size_t ind[3] = {3, 5, 6};
    for (std::size_t k = 0; k < 3; ++k) CHECK(dx[6 + k] == Approx(c.ud[ind[k]]).margin(1e-12).epsilon(1e-12));
  }
}
