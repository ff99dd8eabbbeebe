// Kane's equations of a nonholonomic system (dynamics/equations.hpp, reduced): the rolling
// disc of examples/models/disc.hpp against SymPy's KanesMethod (tests/data/gen_disc_dynamics.py)
// and the closed-form condition of steady turning; the disc in three coordinates, its centre
// known by its velocity (point_by_velocity).
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "../examples/models/disc.hpp"
#include "data/sympy_disc_dynamics.hpp"
#include "data/sympy_disc_mixed.hpp"

namespace {
namespace dd = models::disc;
using disc_state = kane::state<double, 5, 5, 3>;
using disc_evaluator =
    kane::evaluator<disc_state, kane::frames<dd::R>, kane::level::acceleration, dd::speeds5>;

// The disc's inertia given in the leaning frame L, in which R turns about the symmetry axis l2.
using lean_system = kane::system<
    kane::rigid_body<dd::R, dd::Centre5, dd::m,
                     kane::inertia<dd::L, dd::Centre5, dd::diametral, 2 * dd::diametral, dd::diametral>>,
    kane::gravity<-dd::g * kane::e<dd::N, 3>>>;

// u' of all five speeds by Kane's reduced equations at (q, u).
template <class Sys = dd::system>
Eigen::Matrix<double, 5, 1> disc_rates(const double (&q)[5], const double (&u)[5], double* t = nullptr,
                                       double* v = nullptr) {
  disc_state s;
  for (int i = 0; i < 5; ++i) s.q[i] = q[i], s.u[i] = u[i];
  for (int i = 0; i < 3; ++i) s.p[i] = sympy_disc_dynamics::p[i];
  disc_evaluator ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<dd::rolling>(ev);
  REQUIRE(sol.status == kane::solve_status::ok);
  CHECK((sol.A * Eigen::Vector3d(u[0], u[1], u[2]) + sol.B - Eigen::Vector2d(u[3], u[4])).norm() < 1e-14);
  const auto eq = kane::reduced_mass_matrix_and_forcing<Sys, dd::rolling>(ev, sol);
  const auto [ui, st] = kane::speed_derivatives(eq.reduced);
  REQUIRE(st == kane::solve_status::ok);
  if (t) *t = kane::kinetic_energy<Sys>(ev);
  if (v) *v = s.p[1] * s.p[2] * kane::evaluate(dd::height, ev);
  return eq.T * ui + eq.b;
}
}  // namespace

TEST_CASE("dynamics: the rolling disc's reduced equations against SymPy's KanesMethod") {
  for (const auto& x : sympy_disc_dynamics::disc) {
    double t = 0, v = 0;
    const auto ud = disc_rates(x.q, x.u, &t, &v);
    for (int i = 0; i < 5; ++i) CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-12).margin(1e-13));
    CHECK(t == Approx(x.T).epsilon(1e-14));
    CHECK(v == Approx(x.V).epsilon(1e-14));
  }
}

namespace {
// The n equations with their constraint rows (constraints NH) against SymPy's M, f and u' at its cases.
template <class NH, class Cases>
void check_constraint_rows(const Cases& cases, const double (&p)[3]) {
  for (const auto& x : cases) {
    disc_state s;
    for (int i = 0; i < 5; ++i) s.q[i] = x.q[i], s.u[i] = x.u[i];
    for (int i = 0; i < 3; ++i) s.p[i] = p[i];
    disc_evaluator ev;
    ev.update(s);
    const auto sol = kane::solve_constraints<NH>(ev);
    const auto eq = kane::constrained_mass_matrix_and_forcing<dd::system, NH>(ev, sol);
    REQUIRE(eq.status == kane::solve_status::ok);
    for (int i = 0; i < 5; ++i) {
      CHECK(eq.f(i) == Approx(x.f[i]).epsilon(1e-12).margin(1e-13));
      for (int j = 0; j < 5; ++j) CHECK(eq.M(i, j) == Approx(x.M[5 * i + j]).epsilon(1e-12).margin(1e-14));
    }
    const Eigen::Matrix<double, 5, 1> ud = eq.M.partialPivLu().solve(eq.f);
    for (int i = 0; i < 5; ++i) CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-12).margin(1e-13));
  }
}
}  // namespace

TEST_CASE("dynamics: the disc's n equations with their constraint rows equal SymPy's M and f") {
  check_constraint_rows<dd::rolling>(sympy_disc_dynamics::disc, sympy_disc_dynamics::p);
}

TEST_CASE("dynamics: constraint rows whose dependent block is not the identity equal SymPy's M and f") {
  // c1 = 2 vB.n1 + vB.n2, c2 = vB.n1 - 3 vB.n2: SymPy's rows are C u' = -(C' u + c0'), C the
  // constraints' Jacobian as written
  using kane::dot;
  using kane::e;
  using mixed =
      kane::nonholonomic<dd::speeds5, kane::dependent<4, 5>,
                         kane::constant<2>{} * dot(dd::v_below, e<dd::N, 1>) + dot(dd::v_below, e<dd::N, 2>),
                         dot(dd::v_below, e<dd::N, 1>) - kane::constant<3>{} * dot(dd::v_below, e<dd::N, 2>)>;
  check_constraint_rows<mixed>(sympy_disc_mixed::disc, sympy_disc_mixed::p);
}

TEST_CASE("dynamics: an axisymmetric inertia given in the frame the disc turns in") {
  for (const auto& x : sympy_disc_dynamics::disc) {
    double t = 0;
    const auto ud = disc_rates<lean_system>(x.q, x.u, &t);
    for (int i = 0; i < 5; ++i) CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-12).margin(1e-13));
    CHECK(t == Approx(x.T).epsilon(1e-14));
  }
}

TEST_CASE("dynamics: the disc turns steadily where the closed form says so") {
  for (const auto& x : sympy_disc_dynamics::steady) {
    const auto ud = disc_rates(x.q, x.u);
    CHECK(std::abs(ud(0)) < 1e-13);  // u2 = sin(theta) (W^2 r cos(theta) - 4 g) / (6 W r cos(theta))
    CHECK(std::abs(ud(1)) < 1e-13);
    CHECK(std::abs(ud(2)) < 1e-13);
    for (int i = 3; i < 5; ++i) CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-12));
  }
}

TEST_CASE("dynamics: the disc's generalized forces along its nonholonomic partial velocities") {
  for (const auto& x : sympy_disc_dynamics::disc) {
    disc_state s;
    for (int i = 0; i < 5; ++i) s.q[i] = x.q[i], s.u[i] = x.u[i];
    for (int i = 0; i < 3; ++i) s.p[i] = sympy_disc_dynamics::p[i];
    const auto ud = disc_rates(x.q, x.u);  // u' by the reduced equations, summed along v~ directly
    for (int i = 0; i < 5; ++i) s.ud[i] = ud(i);
    disc_evaluator ev;
    ev.update(s);
    const auto sol = kane::solve_constraints<dd::rolling>(ev);
    const auto g = kane::reduced_generalized_forces<dd::system, dd::rolling>(ev, sol);
    REQUIRE(g.status == kane::solve_status::ok);
    // Kane's equations along v~ hold at that u': F~ + F~* = 0
    CHECK((g.active + g.inertia).norm() < 1e-12 * g.inertia.norm());
    // gravity alone acts at the centre, whose height is r cos(q2): with u1 = q2' (the lean rate) its
    // work rate is m g r sin(q2) u1, and u2, u3 do no work
    const double m = s.p[1], gr = s.p[2], r = s.p[0], lean = x.q[1];
    CHECK(g.active(0) == Approx(m * gr * r * std::sin(lean)).epsilon(1e-13).margin(1e-14));
    CHECK(std::abs(g.active(1)) < 1e-14);
    CHECK(std::abs(g.active(2)) < 1e-14);
  }
}

TEST_CASE("dynamics: the disc in three coordinates, its centre known by its velocity, against SymPy") {
  using state3 = kane::state<double, 3, 3, 3>;
  using evaluator3 = kane::evaluator<state3, kane::frames<dd::R>, kane::level::acceleration, dd::speeds3>;
  static_assert(!kane::fixed_in_v<dd::Centre3, dd::N>);
  for (std::size_t k = 0; k < std::size(sympy_disc_dynamics::disc); ++k) {
    const auto& x = sympy_disc_dynamics::disc[k];
    const auto& y = sympy_disc_dynamics::disc3[k];
    state3 s;
    for (int i = 0; i < 3; ++i) s.q[i] = x.q[i], s.u[i] = x.u[i], s.p[i] = sympy_disc_dynamics::p[i];
    evaluator3 ev;
    ev.update(s);
    const auto eq = kane::mass_matrix_and_forcing<dd::system3>(ev);
    REQUIRE(eq.status == kane::solve_status::ok);
    for (int i = 0; i < 3; ++i) {
      CHECK(eq.f(i) == Approx(y.f[i]).epsilon(1e-12).margin(1e-13));
      for (int j = 0; j < 3; ++j) CHECK(eq.M(i, j) == Approx(y.M[3 * i + j]).epsilon(1e-12).margin(1e-14));
    }
    const auto [ud, st] = kane::speed_derivatives(eq);
    REQUIRE(st == kane::solve_status::ok);
    for (int i = 0; i < 3; ++i) {
      CHECK(ud(i) == Approx(y.ud[i]).epsilon(1e-12).margin(1e-13));
      CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-12).margin(1e-13));  // = the five-coordinate disc's
    }
    CHECK(kane::kinetic_energy<dd::system3>(ev) == Approx(x.T).epsilon(1e-14));
    // momenta: those of the five-coordinate disc (its centre located from an origin)
    disc_state s5;
    for (int i = 0; i < 5; ++i) s5.q[i] = x.q[i], s5.u[i] = x.u[i];
    for (int i = 0; i < 3; ++i) s5.p[i] = sympy_disc_dynamics::p[i];
    disc_evaluator ev5;
    ev5.update(s5);
    CHECK(kane::is_approx(kane::linear_momentum<dd::system3>(ev), kane::linear_momentum<dd::system>(ev5),
                          1e-14));
    CHECK(kane::is_approx(kane::angular_momentum<dd::system3>(ev), kane::angular_momentum<dd::system>(ev5),
                          1e-14));
    // ^N a of the centre = ^N d(w x r l3)/dt: against a central difference of its velocity along
    // the motion (q' from the kinematic equations, u' from Kane's)
    const auto centre = [&](const state3& z) {
      evaluator3 e;
      e.update(z);
      return kane::express<dd::N>(kane::velocity<dd::N, dd::Centre3>(), e).eigen();
    };
    s.ud = {ud(0), ud(1), ud(2)};
    ev.update(s);
    const Eigen::Vector3d a = kane::express<dd::N>(kane::acceleration<dd::N, dd::Centre3>(), ev).eigen();
    const double h = 1e-5;
    const Eigen::Vector3d qd(x.u[2] / std::cos(x.q[1]), x.u[0], x.u[1] - x.u[2] * std::tan(x.q[1]));
    state3 plus = s, minus = s;
    for (int i = 0; i < 3; ++i) {
      plus.q[i] += h * qd(i), minus.q[i] -= h * qd(i);
      plus.u[i] += h * ud(i), minus.u[i] -= h * ud(i);
    }
    CHECK(((centre(plus) - centre(minus)) / (2 * h) - a).norm() < 1e-6 * (1 + a.norm()));
  }
}

TEST_CASE("dynamics: kane::constrained_motion with vectors of another run-time size says wrong_size") {
  disc_state s;
  for (int i = 0; i < 3; ++i) s.p[i] = sympy_disc_dynamics::p[i];
  kane::constrained_motion<dd::system, dd::rolling, disc_evaluator> f(s);
  const Eigen::VectorXd right = Eigen::VectorXd::Constant(8, 0.3), wrong = Eigen::VectorXd::Constant(5, 0.3);
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(8), short_dx = Eigen::VectorXd::Zero(3);
  f(wrong, dx, 0.0);  // x of 5 numbers, not nq + p = 8: nothing read beyond them
  CHECK(f.status() == kane::solve_status::wrong_size);
  CHECK(dx.array().isNaN().all());
  f(right, short_dx, 0.0);  // dx/dt of 3: nothing written beyond it
  CHECK(f.status() == kane::solve_status::wrong_size);
  CHECK(short_dx.array().isNaN().all());
  f(right, dx, 0.0);
  CHECK(f.status() == kane::solve_status::ok);
  CHECK(dx.allFinite());
}

TEST_CASE("dynamics: kane::constrained_motion names x's entries and gives the evaluator at a state of x") {
  disc_state s;
  for (int i = 0; i < 3; ++i) s.p[i] = sympy_disc_dynamics::p[i];
  kane::constrained_motion<dd::system, dd::rolling, disc_evaluator> f(s);
  STATIC_REQUIRE((f.index(kane::q<5>) == 4 && f.index(kane::u<1>) == 5 && f.index(kane::u<3>) == 7));
  const std::array<double, 8> stage{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7},
      x{0.2, 0.35, 0.1, 0.5, -0.3, 0.4, 5.0, 1.1};
  std::array<double, 8> dx{};
  f(x, dx, 0.0);
  const auto at_x = f.state();  // u4, u5 solved at x
  f(stage, dx, 0.0);
  const auto ev = f.evaluator(x, 0.0);
  REQUIRE(ev.status() == kane::solve_status::ok);
  for (std::size_t i = 0; i < 5; ++i) CHECK(ev.state().u[i] == Approx(at_x.u[i]).epsilon(1e-15));
  CHECK(f.evaluator(Eigen::VectorXd::Zero(5), 0.0).status() == kane::solve_status::not_finite);
}

TEST_CASE("dynamics: kane::constrained_motion checks once a call: x and the state, the rank, dx/dt") {
  disc_state s;
  for (int i = 0; i < 3; ++i) s.p[i] = sympy_disc_dynamics::p[i];
  kane::constrained_motion<dd::system, dd::rolling, disc_evaluator> f(s);
  const std::array<double, 8> good{0.2, 0.35, 0.1, 0.5, -0.3, 0.4, 5.0, 1.1};
  std::array<double, 8> dx{};
  const auto all_nan = [&] {
    return std::all_of(dx.begin(), dx.end(), [](double v) { return std::isnan(v); });
  };
  f(good, dx, 0.0);
  REQUIRE(f.status() == kane::solve_status::ok);
  // NaN or inf at any entry of x, q3..q5 included, which no rate reads
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    for (std::size_t i = 0; i < 8; ++i) {
      auto x = good;
      x[i] = bad;
      f(x, dx, 0.0);
      CHECK(f.status() == kane::solve_status::not_finite);
      CHECK(all_nan());
    }
  // finite speeds whose products overflow: u_ind' is not finite, and so is none of dx/dt
  auto fast = good;
  fast[5] = fast[6] = fast[7] = 1e200;
  f(fast, dx, 0.0);
  CHECK(f.status() == kane::solve_status::not_finite);
  CHECK(all_nan());
  // a mass that is not finite
  disc_state heavy = s;
  heavy.p[1] = std::numeric_limits<double>::infinity();
  kane::constrained_motion<dd::system, dd::rolling, disc_evaluator> g(heavy);
  g(good, dx, 0.0);
  CHECK(g.status() == kane::solve_status::not_finite);
  CHECK(all_nan());
  // C_dep = [1 0; cos q1 sin q1] fails the rank rule at q1 = 0
  using kane::dot;
  using kane::e;
  using turning = kane::nonholonomic<dd::speeds5, kane::dependent<4, 5>, dot(dd::v_below, e<dd::N, 1>),
                                     kane::cos(kane::q<1>) * dot(dd::v_below, e<dd::N, 1>) +
                                         kane::sin(kane::q<1>) * dot(dd::v_below, e<dd::N, 2>)>;
  kane::constrained_motion<dd::system, turning, disc_evaluator> h(s);
  std::array<double, 8> rolling{};
  f(good, rolling, 0.0);
  h(good, dx, 0.0);  // the same constraints where sin q1 is not 0
  CHECK(h.status() == kane::solve_status::ok);
  for (std::size_t i = 0; i < 8; ++i) CHECK(dx[i] == Approx(rolling[i]).epsilon(1e-13));
  auto straight = good;
  straight[0] = 0.0;
  h(straight, dx, 0.0);
  CHECK(h.status() == kane::solve_status::singular);
  CHECK(all_nan());
}
