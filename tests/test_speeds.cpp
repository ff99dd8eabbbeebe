#include <catch2/catch.hpp>

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <random>

#include "../examples/models/disc.hpp"
#include "data/sympy_speeds.hpp"
#include "trees.hpp"

using kane::dot;
using kane::e;
using trees::N;

namespace {
template <std::size_t I>
using q = kane::coordinate<I>;

// The rolling disc of examples/models/disc.hpp (yaw q1 about n3, lean q2 about y1, spin q3 about
// l2), rooted at its own Newtonian frame DN.
namespace disc = models::disc;
using DN = disc::N;
using disc::w, disc::v_centre, disc::rolling;
using disc::Y, disc::L, disc::R, disc::C, disc::Centre, disc::O, disc::Contact, disc::Centre5, disc::Below;
inline constexpr auto v_contact = disc::v_below;
using disc3_speeds = disc::speeds3;  // u1..u3: ^N w^R in L
using disc5_speeds = disc::speeds5;
static_assert(std::is_same_v<disc3_speeds, kane::angular_velocity_speeds<DN, R, L>>);
static_assert(rolling::p == 3 && rolling::independents == std::array<std::size_t, 3>{1, 2, 3});

using St3 = kane::state<double, 3, 3, 1>;
using St5 = kane::state<double, 5, 5, 1>;
using Ev3 = kane::evaluator<St3, kane::frames<R>, kane::level::velocity, disc3_speeds>;
using Ev5 = kane::evaluator<St5, kane::frames<R>, kane::level::velocity, disc5_speeds>;

template <class M>
double max_diff(const M& m, const double* rowmajor) {
  double d = 0;
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) d = std::fmax(d, std::fabs(m(i, j) - rowmajor[i * m.cols() + j]));
  return d;
}

// Symbolic partials with u = q': type-level, no evaluator numbers involved.
using q6 = kane::qdot_speeds<6>;
static_assert(std::is_same_v<decltype(kane::partial_velocity<q6>(kane::dt(kane::q<2>) * e<N, 1>, kane::u<2>)),
                             kane::unit<N, 1>>);
static_assert(std::is_same_v<decltype(kane::partial_velocity<q6>(kane::dt(kane::q<2>) * e<N, 1>, kane::u<3>)),
                             kane::zero_vector>);
template <class X, class Leaf>
concept has_partial = requires(X x, Leaf l) {
  kane::partial_velocity<q6>(x, l);
};
// by a coordinate: found and rejected by a static assertion naming the rule (compile_fail/speeds)
static_assert(has_partial<kane::unit<N, 1>, kane::speed<1>> &&
              has_partial<kane::unit<N, 1>, kane::coordinate<1>>);
}  // namespace

TEST_CASE(
    "speeds: the rolling disc's kinematic differential equations and partial velocities against SymPy") {
  for (const auto& c : sympy_speeds::disc) {
    St3 s;
    s.q = {c.q[0], c.q[1], c.q[2]};
    s.u = {c.u[0], c.u[1], c.u[2]};
    s.p = {c.r};
    Ev3 ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    CHECK(ev.coordinate_value<1, 1>() == Approx(c.qd[0]).margin(1e-13));
    CHECK(ev.coordinate_value<2, 1>() == Approx(c.qd[1]).margin(1e-13));
    CHECK(ev.coordinate_value<3, 1>() == Approx(c.qd[2]).margin(1e-13));
    // ^N w^R in L equals u.
    const auto wL = kane::express<L>(w, ev);
    for (int i = 0; i < 3; ++i) CHECK(wL[i] == Approx(c.u[i]).margin(1e-13));
    const auto vc = kane::express<DN>(v_centre, ev);
    for (int i = 0; i < 3; ++i) CHECK(vc[i] == Approx(c.vc_N[i]).margin(1e-13));
    const auto V = kane::partial_velocities<DN>(v_centre, ev);
    const auto Wt = kane::partial_velocities<DN>(w, ev);
    CHECK(max_diff(V, c.vc_partials) < 1e-13);
    CHECK(max_diff(Wt, c.w_partials) < 1e-13);
    // Closed forms: v_1 = -r l2, v_2 = r l1, v_3 = 0; w_r = l_r; remainders zero.
    const auto l = ev.axes<L>();
    CHECK((V.col(0) + c.r * l.col(1)).norm() < 1e-14);
    CHECK((V.col(1) - c.r * l.col(0)).norm() < 1e-14);
    CHECK(V.col(2).norm() < 1e-14);
    CHECK((Wt - l).norm() < 1e-14);
    CHECK(kane::remainder<DN>(v_centre, ev).norm() < 1e-14);
    // v = sum v_r u_r + v_t
    const Eigen::Vector3d u(c.u[0], c.u[1], c.u[2]);
    CHECK((V * u + kane::remainder<DN>(v_centre, ev) - vc.eigen()).norm() < 1e-13);
  }
}

TEST_CASE("speeds: the five-coordinate disc's constraints, A, B and nonholonomic partial velocities") {
  for (const auto& c : sympy_speeds::disc) {
    St5 s;
    for (int i = 0; i < 5; ++i) s.q[i] = c.q[i], s.u[i] = c.u[i];
    s.p = {c.r};
    Ev5 ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto sol = kane::solve_constraints<rolling>(ev);
    REQUIRE(sol.status == kane::solve_status::ok);
    CHECK(max_diff(sol.A, c.A) < 1e-13);
    CHECK(std::abs(sol.B(0) - c.B[0]) < 1e-14);
    CHECK(std::abs(sol.B(1) - c.B[1]) < 1e-14);
    // Closed form: u4 = r c1 (u2 - tan q2 u3), u5 = r s1 (u2 - tan q2 u3).
    const double c1 = std::cos(c.q[0]), s1 = std::sin(c.q[0]), t2 = std::tan(c.q[1]);
    Eigen::Matrix<double, 2, 3> A;
    A << 0, c.r * c1, -c.r * c1 * t2, 0, c.r * s1, -c.r * s1 * t2;
    CHECK((sol.A - A).cwiseAbs().maxCoeff() < 1e-13);
    // The nonholonomic partial velocities of the centre equal the holonomic
    // ones of the three-coordinate disc; so do the partial angular velocities.
    const auto v5 = kane::velocity<DN, Centre5>();
    const auto Vnh = kane::nonholonomic_partial_velocities<DN, rolling>(v5, ev, sol);
    CHECK(max_diff(Vnh, c.v5_partials) < 1e-13);
    CHECK(max_diff(Vnh, c.vc_partials) < 1e-13);
    CHECK(max_diff(kane::nonholonomic_partial_velocities<DN, rolling>(w, ev, sol), c.w_partials) < 1e-13);
    CHECK(kane::nonholonomic_remainder<DN, rolling>(v5, ev, sol).norm() < 1e-14);
    // Constraints hold for u_dep = A u_ind + B: the contact point is at rest.
    St5 s2 = s;
    const Eigen::Vector3d ui(c.u[0], c.u[1], c.u[2]);
    const Eigen::Vector2d ud = sol.A * ui + sol.B;
    s2.u[3] = ud(0);
    s2.u[4] = ud(1);
    Ev5 ev2;
    ev2.update(s2);
    CHECK(kane::express<DN>(v_contact, ev2).eigen().norm() < 1e-13);
  }
}

TEST_CASE("speeds: law tests over random states: v = sum v_r u_r + v_t, constraints satisfied") {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> d(-1.3, 1.3);
  for (int k = 0; k < 300; ++k) {
    St5 s;
    for (int i = 0; i < 5; ++i) s.q[i] = d(rng), s.u[i] = 2 * d(rng);
    s.p = {0.2 + std::abs(d(rng))};
    Ev5 ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto v5 = kane::velocity<DN, Centre5>();
    const Eigen::Matrix<double, 5, 1> u = Eigen::Map<const Eigen::Matrix<double, 5, 1>>(s.u.data());
    CHECK((kane::partial_velocities<DN>(v5, ev) * u + kane::remainder<DN>(v5, ev) -
           kane::express<DN>(v5, ev).eigen())
              .norm() < 1e-12);
    CHECK((kane::partial_velocities<DN>(w, ev) * u + kane::remainder<DN>(w, ev) -
           kane::express<DN>(w, ev).eigen())
              .norm() < 1e-12);
    const auto sol = kane::solve_constraints<rolling>(ev);
    St5 s2 = s;
    const Eigen::Vector2d ud = sol.A * u.head<3>() + sol.B;
    s2.u[3] = ud(0);
    s2.u[4] = ud(1);
    Ev5 ev2;
    ev2.update(s2);
    CHECK(kane::express<DN>(v_contact, ev2).eigen().norm() < 1e-12);
    // With the dependent speeds from the constraints, v = sum v~_s u_s + v~_t.
    const auto Vnh = kane::nonholonomic_partial_velocities<DN, rolling>(v5, ev2, sol);
    CHECK((Vnh * u.head<3>() + kane::nonholonomic_remainder<DN, rolling>(v5, ev2, sol) -
           kane::express<DN>(v5, ev2).eigen())
              .norm() < 1e-12);
  }
}

TEST_CASE("speeds: a singular dependent block gives NaN and a status, never a trap") {
  {
    // u1 + u2 + u3 = 0 and 2 u1 + 2 u2 + 2 u3 = 1: the block of u2, u3 is singular.
    using kane::u;
    using nh = kane::nonholonomic<kane::qdot_speeds<3>, kane::dependent<2, 3>, u<1> + u<2> + u<3>,
                                  2.0 * (u<1> + u<2> + u<3>)-1.0>;
    kane::state<double, 3> s;
    kane::evaluator<kane::state<double, 3>, kane::frames<Y>, kane::level::velocity> ev;
    ev.update(s);
    const auto sol = kane::solve_constraints<nh>(ev);
    CHECK(sol.status == kane::solve_status::singular);
    CHECK(std::isnan(sol.A(1, 0)));
    CHECK(std::isnan(sol.B(0)));
  }
  // Upright and spinning about the vertical with q2 = pi/2: tan q2 blows up; at
  // q2 = pi/2 exactly the lean speeds cannot be solved: Y is singular.
  St5 s;
  s.q = {0.3, std::acos(-1.0) / 2, 0.1, 0, 0};
  s.u = {1, 1, 1, 0, 0};
  s.p = {0.5};
  Ev5 ev;
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::singular);
  CHECK(std::isnan(ev.coordinate_value<1, 1>()));
  CHECK(std::isnan(kane::express<DN>(v_contact, ev)[0]));
  const auto sol = kane::solve_constraints<rolling>(ev);
  CHECK(sol.status != kane::solve_status::ok);
  CHECK(std::isnan(sol.A(0, 0)));
  // NaN in the state: not finite.
  s.q[1] = std::numeric_limits<double>::quiet_NaN();
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::not_finite);
}

namespace {
struct B321 : kane::frame<N, kane::body_fixed<3, 2, 1, q<1>, q<2>, q<3>>> {};
inline constexpr auto wb = kane::angular_velocity<N, B321>();
using body_speeds = kane::speeds<dot(wb, e<B321, 1>), dot(wb, e<B321, 2>), dot(wb, e<B321, 3>)>;
using St321 = kane::state<double, 3>;
using Ev321 = kane::evaluator<St321, kane::frames<B321>, kane::level::acceleration, body_speeds>;
}  // namespace

TEST_CASE("speeds: a 3-2-1 body with body-frame angular velocity components as speeds") {
  for (const auto& c : sympy_speeds::body321) {
    St321 s;
    s.q = {c.q[0], c.q[1], c.q[2]};
    s.u = {c.u[0], c.u[1], c.u[2]};
    Ev321 ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    // Closed form: psi' = (u2 s3 + u3 c3)/c2, theta' = u2 c3 - u3 s3, phi' = u1 + (u2 s3 + u3 c3) tan q2.
    const double s3 = std::sin(c.q[2]), c3 = std::cos(c.q[2]), c2 = std::cos(c.q[1]), t2 = std::tan(c.q[1]);
    const double a = c.u[1] * s3 + c.u[2] * c3;
    CHECK(ev.coordinate_value<1, 1>() == Approx(a / c2).margin(1e-13));
    CHECK(ev.coordinate_value<2, 1>() == Approx(c.u[1] * c3 - c.u[2] * s3).margin(1e-13));
    CHECK(ev.coordinate_value<3, 1>() == Approx(c.u[0] + a * t2).margin(1e-13));
    CHECK(ev.coordinate_value<1, 1>() == Approx(c.qd[0]).margin(1e-13));
    CHECK(ev.coordinate_value<2, 1>() == Approx(c.qd[1]).margin(1e-13));
    CHECK(ev.coordinate_value<3, 1>() == Approx(c.qd[2]).margin(1e-13));
  }
  // The speeds' derivatives give q'': the body's angular acceleration in B is u'.
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> d(-1.2, 1.2);
  for (int k = 0; k < 100; ++k) {
    St321 s;
    for (int i = 0; i < 3; ++i) s.q[i] = d(rng), s.u[i] = d(rng), s.ud[i] = d(rng);
    Ev321 ev;
    ev.update(s);
    const auto alpha = kane::express<B321>(kane::angular_acceleration<N, B321>(), ev);
    for (int i = 0; i < 3; ++i) CHECK(alpha[i] == Approx(s.ud[i]).margin(1e-12));
    // the solved q' and q'' turn the frames edge by edge to the same alpha
    kane::state<double, 3> t;
    t.q = s.q, t.qd = ev.coordinate_rates<1>(), t.qdd = ev.coordinate_rates<2>();
    kane::evaluator<kane::state<double, 3>, kane::frames<B321>> chain;
    chain.update(t);
    const auto by_edges = kane::express<B321>(kane::angular_acceleration<N, B321>(), chain);
    for (int i = 0; i < 3; ++i) CHECK(by_edges[i] == Approx(s.ud[i]).margin(1e-12));
  }
  // Gimbal lock: q2 = pi/2 makes Y singular.
  St321 s;
  s.q = {0.2, std::acos(-1.0) / 2, -0.4};
  s.u = {0.1, 0.2, 0.3};
  Ev321 ev;
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::singular);
  CHECK(std::isnan(ev.coordinate_value<2, 1>()));
  CHECK(std::isnan(kane::express<N>(wb, ev)[0]));
  // NaN in the coupled block (q1', q2'): not finite rather than singular.
  s.q[1] = std::numeric_limits<double>::quiet_NaN();
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::not_finite);
  CHECK(std::isnan(ev.coordinate_value<3, 1>()));
}

TEST_CASE("speeds: update_pose then update_speeds gives the numbers and status of update") {
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> d(-1.2, 1.2);
  const auto alpha = kane::angular_acceleration<N, B321>();
  for (int k = 0; k < 50; ++k) {
    St321 s;
    for (int i = 0; i < 3; ++i) s.q[i] = d(rng), s.u[i] = d(rng), s.ud[i] = d(rng);
    Ev321 whole, split;
    whole.update(s);
    split.update_pose(s);
    REQUIRE(split.status() == kane::solve_status::ok);
    CHECK(kane::express<N>(e<B321, 2>, split) == kane::express<N>(e<B321, 2>, whole));
    St321 later = s;  // update_speeds reads u and u' only: the pose stays that of update_pose
    later.q = {9, 9, 9};
    split.update_speeds(later);
    REQUIRE(split.status() == kane::solve_status::ok);
    CHECK(split.coordinate_rates<1>() == whole.coordinate_rates<1>());
    CHECK(split.coordinate_rates<2>() == whole.coordinate_rates<2>());
    CHECK(kane::express<N>(alpha, split) == kane::express<N>(alpha, whole));
  }
  // NaN in u: the pose is ok, the speeds are not finite.
  St321 s;
  s.q = {0.2, 0.3, -0.4};
  s.u = {0.1, std::numeric_limits<double>::quiet_NaN(), 0.3};
  Ev321 ev;
  ev.update_pose(s);
  CHECK(ev.status() == kane::solve_status::ok);
  ev.update_speeds(s);
  CHECK(ev.status() == kane::solve_status::not_finite);
  CHECK(std::isnan(ev.coordinate_value<1, 1>()));
  // Gimbal lock found by the pose stays the status: singular, not overwritten by finite speeds.
  s.q[1] = std::acos(-1.0) / 2;
  s.u[1] = 0.2;
  ev.update_pose(s);
  ev.update_speeds(s);
  CHECK(ev.status() == kane::solve_status::singular);
  CHECK(std::isnan(ev.coordinate_value<2, 1>()));
}

namespace {
using namespace trees;
struct A1 : kane::frame<N, kane::simple<kane::axis::z, trees::q1>> {};
struct A2 : kane::frame<A1, kane::simple<kane::axis::y, trees::q2>> {};
struct A3 : kane::frame<A2, kane::simple<kane::axis::y, trees::q3>> {};
struct A4 : kane::frame<A3, kane::simple<kane::axis::x, trees::q4>> {};
struct A5 : kane::frame<A4, kane::simple<kane::axis::y, trees::q5>> {};
struct A6 : kane::frame<A5, kane::simple<kane::axis::x, trees::q6>> {};
struct O6 : kane::origin<N> {};
struct End : kane::point<O6, 0.3 * e<A1, 1> + 0.25 * e<A2, 1> + 0.2 * e<A3, 1> + 0.15 * e<A4, 1> +
                                 0.1 * e<A5, 1> + 0.05 * e<A6, 1>> {};
}  // namespace

TEST_CASE("speeds: the 6x6 geometric Jacobian of a 6-revolute arm, and J u is the velocity") {
  using St = kane::state<double, 6>;
  const auto wE = kane::angular_velocity<N, A6>();
  const auto vE = kane::velocity<N, End>();
  for (const auto& c : sympy_speeds::arm_jacobian) {
    St s;
    for (int i = 0; i < 6; ++i) s.q[i] = c.q[i];
    kane::evaluator<St, kane::frames<A6>, kane::level::velocity> ev;
    ev.update(s);
    Eigen::Matrix<double, 6, 6> J;
    J << kane::partial_velocities<N>(wE, ev), kane::partial_velocities<N>(vE, ev);
    CHECK(max_diff(J, c.J) < 1e-13);
  }
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> d(-3, 3);
  for (int k = 0; k < 300; ++k) {
    St s;
    for (int i = 0; i < 6; ++i) s.q[i] = d(rng), s.qd[i] = d(rng);
    kane::evaluator<St, kane::frames<A6>, kane::level::velocity> ev;
    ev.update(s);
    Eigen::Matrix<double, 6, 6> J;
    J << kane::partial_velocities<N>(wE, ev), kane::partial_velocities<N>(vE, ev);
    const Eigen::Matrix<double, 6, 1> u = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(s.qd.data());
    Eigen::Matrix<double, 6, 1> twist;
    twist << kane::express<N>(wE, ev).eigen(), kane::express<N>(vE, ev).eigen();
    CHECK((J * u - twist).norm() < 1e-12);
  }
}

TEST_CASE("speeds: holonomic constraints, their residuals, velocity constraints and n = 3v - M") {
  // Two particles (x1, y1, z1, x2, y2, z2) = q1..q6 of a planar double pendulum.
  using kane::q;
  struct L1 : kane::parameter<1> {};
  struct L2 : kane::parameter<2> {};
  constexpr L1 l1;
  constexpr L2 l2;
  using cfg =
      kane::configuration<2, 0, q<3>, q<6>, kane::pow<2>(q<1>) + kane::pow<2>(q<2>) - kane::pow<2>(l1),
                          kane::pow<2>(q<4> - q<1>) + kane::pow<2>(q<5> - q<2>) - kane::pow<2>(l2)>;
  static_assert(cfg::constraints == 4 && cfg::n == 2);
  static_assert(kane::configuration<0, 1>::n == 6);
  using St = kane::state<double, 6, 6, 2>;
  St s;
  const double a = 0.4, b = 1.1, la = 1.2, lb = 0.7;
  s.p = {la, lb};
  s.q = {la * std::cos(a),
         la * std::sin(a),
         0,
         la * std::cos(a) + lb * std::cos(a + b),
         la * std::sin(a) + lb * std::sin(a + b),
         0};
  s.qd = {0.3, -0.2, 0.1, 0.5, 0.4, -0.6};
  kane::evaluator<St, kane::frames<N>, kane::level::pose> ev;
  ev.update(s);
  for (double r : kane::residuals<cfg>(ev)) CHECK(std::abs(r) < 1e-14);
  s.q[0] += 0.01;  // off the constraint surface
  ev.update(s);    // the evaluator holds a copy of the state of its last update
  const auto res = kane::residuals<cfg>(ev);
  const double x1 = s.q[0], y1 = s.q[1];
  CHECK(res[2] == Approx(x1 * x1 + y1 * y1 - la * la));
  // df/dt = 2 x1 x1' + 2 y1 y1' for the third; z1' for the first.
  const auto vres = kane::velocity_residuals<cfg>(ev);
  CHECK(vres[0] == Approx(0.1));
  CHECK(vres[2] == Approx(2 * x1 * 0.3 + 2 * y1 * -0.2));
  const double dx = s.q[3] - x1, dy = s.q[4] - y1;
  CHECK(vres[3] == Approx(2 * dx * (0.5 - 0.3) + 2 * dy * (0.4 + 0.2)));
}

TEST_CASE("speeds: qdot_speeds read u and u' as q' and q''") {
  using St = kane::state<double, 6>;
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> d(-2, 2);
  const auto aE = kane::acceleration<N, End>();
  for (int k = 0; k < 50; ++k) {
    St s, t;
    for (int i = 0; i < 6; ++i)
      s.q[i] = t.q[i] = d(rng), s.qd[i] = t.u[i] = d(rng), s.qdd[i] = t.ud[i] = d(rng);
    kane::evaluator<St, kane::frames<A6>> from_q;
    kane::evaluator<St, kane::frames<A6>, kane::level::acceleration, kane::qdot_speeds<6>> from_u;
    from_q.update(s);
    from_u.update(t);
    CHECK(from_u.status() == kane::solve_status::ok);
    CHECK(kane::is_approx(kane::express<N>(aE, from_u), kane::express<N>(aE, from_q), 1e-14));
  }
}

TEST_CASE("speeds: the inverse behind the kinematic equations agrees with Eigen's FullPivLU on rank") {
  using M = Eigen::Matrix<double, 4, 4>;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-1, 1);
  int singular = 0;
  for (int k = 0; k < 400; ++k) {
    M m = M::NullaryExpr([&] { return d(rng); });
    // every other matrix: the last row a combination of two others, disturbed by 0 .. 1e-12
    if (k % 2) m.row(3) = 0.3 * m.row(0) - 0.7 * m.row(1) + std::pow(10.0, -12 - k % 7) * (k % 3) * m.row(2);
    if (k % 50 == 0) m *= 1e-200;  // scale does not decide rank
    Eigen::FullPivLU<M> lu;
    lu.setThreshold(std::numeric_limits<double>::epsilon() * 4);
    lu.compute(m);
    M inv;
    const bool ok = kane::detail::invert(m, inv);
    INFO("k = " << k);
    CHECK(ok == lu.isInvertible());
    singular += !ok;
    if (ok)
      CHECK((m * inv - M::Identity()).lpNorm<Eigen::Infinity>() <
            1e-13 * m.lpNorm<Eigen::Infinity>() * inv.lpNorm<Eigen::Infinity>());
  }
  CHECK(singular > 50);  // the disturbed cases below eps * n relative are found singular
  // A zero diagonal needs pivoting.
  Eigen::Matrix3d p, inv;
  p << 0, 2, 0, 0, 0, 3, 4, 0, 0;
  REQUIRE(kane::detail::invert(p, inv));
  CHECK((p * inv - Eigen::Matrix3d::Identity()).norm() < 1e-15);
  CHECK_FALSE(kane::detail::invert(Eigen::Matrix3d::Zero().eval(), inv));
}

namespace {
// The structure of Y, read from the types at compile time.
using kane::detail::entry;
using disc5_kde = kane::detail::kde_system<disc5_speeds>;
// u1 = q2', u2 = s2 q1' + q3', u3 = c2 q1', u4 = q4', u5 = q5': n3 . l2 = sin q2 and n3 . l3 = cos q2 by the
// tree
static_assert(std::is_same_v<disc5_kde::y_type<1, 0>, kane::unary<kane::sin_fn, kane::coordinate<2>>>);
static_assert(std::is_same_v<disc5_kde::y_type<2, 0>, kane::unary<kane::cos_fn, kane::coordinate<2>>>);
static_assert(disc5_kde::m[0] == std::array{entry::zero, entry::one, entry::zero, entry::zero, entry::zero});
static_assert(disc5_kde::form.count == 5);  // five blocks of one unknown: substitution, no factorization
// W: q1' = u3 / c2, q2' = u1, q3' = u2 - s2/c2 u3, q4' = u4, q5' = u5; X = 0
static_assert(std::is_same_v<decltype(kane::detail::weight<disc5_speeds, 2, 1>()), kane::one_t>);
static_assert(std::is_same_v<decltype(kane::detail::weight<disc5_speeds, 1, 1>()), kane::zero_t>);
static_assert(std::is_same_v<decltype(kane::detail::weight<disc5_speeds, 1, 3>()),
                             kane::kde_weight<1, 3, disc5_speeds>>);
static_assert(std::is_same_v<decltype(kane::detail::offset<disc5_speeds, 1>()), kane::zero_t>);
// The 3-2-1 body: q1', q2' coupled in one block of two, then q3' from u1 = q3' - s2 q1'.
using body_kde = kane::detail::kde_system<body_speeds>;
}  // namespace

TEST_CASE("speeds: block forms found at compile time solve what a full inverse solves") {
  // The 3-2-1 body: a block of one unknown and a coupled block of two.
  STATIC_REQUIRE(body_kde::form.count == 2);
  STATIC_REQUIRE(body_kde::form.start[1] == 2 && body_kde::form.start[2] == 3);  // q1', q2' first, then q3'
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> d(-1.4, 1.4);
  for (int k = 0; k < 200; ++k) {
    St321 s;
    for (int i = 0; i < 3; ++i) s.q[i] = d(rng), s.u[i] = d(rng);
    Ev321 ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    // W Y = I with Y = du/dq' from the closed form of the 3-2-1 body rates
    const double s2 = std::sin(s.q[1]), c2 = std::cos(s.q[1]), s3 = std::sin(s.q[2]), c3 = std::cos(s.q[2]);
    Eigen::Matrix3d y;
    y << -s2, 0, 1, c2 * s3, c3, 0, c2 * c3, -s3, 0;
    CHECK((ev.W() * y - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    CHECK(ev.X().norm() == 0);
  }
}

TEST_CASE("speeds: partial velocities and constraints need only the pose level") {
  using EvPose = kane::evaluator<St5, kane::frames<L>, kane::level::pose, disc5_speeds>;
  // partials_of: the frames of the centre's velocity and the contact's, at the pose level
  using partials =
      kane::reads<kane::partials_of(kane::velocity<DN, Centre5>()), kane::partials_of(v_contact)>;
  static_assert(partials::needed == kane::level::pose &&
                kane::reads<kane::velocity<DN, Centre5>()>::needed == kane::level::velocity);
  using EvFor = kane::evaluator_for<St5, partials, disc5_speeds>::evaluator_type;
  static_assert(std::is_same_v<EvFor::closure, EvPose::closure>);  // N, Y, L: not R
  for (const auto& c : sympy_speeds::disc) {
    St5 s;
    for (int i = 0; i < 5; ++i) s.q[i] = c.q[i], s.u[i] = c.u[i];
    s.p = {c.r};
    EvFor ev;  // L suffices: nothing here needs the spin angle q3
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto sol = kane::solve_constraints<rolling>(ev);
    REQUIRE(sol.status == kane::solve_status::ok);
    CHECK(max_diff(sol.A, c.A) < 1e-13);
    const auto Vnh =
        kane::nonholonomic_partial_velocities<DN, rolling>(kane::velocity<DN, Centre5>(), ev, sol);
    CHECK(max_diff(Vnh, c.v5_partials) < 1e-13);
  }
  // A singular Y at the pose level: W's numbers and the constraints are NaN, with a status.
  St5 s;
  s.q = {0.3, std::acos(-1.0) / 2, 0.1, 0, 0};
  s.p = {0.5};
  EvPose ev;
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::singular);
  CHECK(std::isnan(ev.W()(0, 2)));
  CHECK(ev.W()(1, 0) == 1.0);  // q2' = u1 whatever q2 is
  CHECK(std::isnan(kane::solve_constraints<rolling>(ev).A(0, 2)));
}

TEST_CASE("speeds: Y with huge or tiny entries: the rank rule is relative, overflow is not finite") {
  // u_r = k q_r' for a parameter k: W = I / k.
  struct K : kane::parameter<1> {};
  constexpr K k;
  using sp = kane::speeds<k * kane::dt(kane::q<1>), k * kane::dt(kane::q<2>)>;
  using St = kane::state<double, 2, 2, 1>;
  kane::evaluator<St, kane::frames<Y>, kane::level::velocity, sp> ev;
  St s;
  s.u = {1, 2};
  for (double scale : {1e-200, 1e-3, 1.0, 1e200}) {
    s.p = {scale};
    ev.update(s);
    CHECK(ev.status() == kane::solve_status::ok);
    CHECK(ev.coordinate_value<2, 1>() == Approx(2 / scale));
  }
  s.p = {1e-310};  // 1/k overflows: W is not finite
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::not_finite);
  CHECK(std::isnan(ev.coordinate_value<1, 1>()));
  s.p = {0.0};
  ev.update(s);
  CHECK(ev.status() == kane::solve_status::singular);
}
