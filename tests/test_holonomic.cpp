// Holonomic constraints solved: the four-bar linkage (examples/models/fourbar.hpp). The
// configuration from Newton's method against the closed form of the triangle P-Q-D, the
// dependent rates u2, u3 = A u1 against central differences of solved configurations, and
// the statuses of a loop that cannot close, a singular Jacobian and NaN input.
#include <catch2/catch.hpp>
#include <cmath>

#include "../examples/models/fourbar.hpp"

namespace {
using namespace models::fourbar;
constexpr double la = 0.3, lb = 1.0, lc = 0.8, ld = 1.1;

state start(double q1) {
  state s;
  s.p = {la, lb, lc, ld};
  s.q = {q1, 0.3, 1.6};  // near the elbow-up branch
  s.u = {1.0, 0.0, 0.0};
  return s;
}
// q2, q3 of the loop closed at q1 (the branch with Q above the line PD): law of cosines.
std::array<double, 2> closed_form(double q1) {
  const double px = la * std::cos(q1), py = la * std::sin(q1);
  const double ex = ld - px, ey = -py, e = std::hypot(ex, ey);
  const double beta = std::acos((lb * lb + e * e - lc * lc) / (2 * lb * e));
  const double q2 = std::atan2(ey, ex) + beta;
  const double qx = px + lb * std::cos(q2), qy = py + lb * std::sin(q2);
  return {q2, std::atan2(qy, qx - ld)};
}
std::array<double, 2> solved(double q1) {
  state s = start(q1);
  evaluator ev;
  const auto r = kane::solve_configuration<loop>(ev, s);
  REQUIRE(r.status == kane::solve_status::ok);
  return {s.q[1], s.q[2]};
}
}  // namespace

TEST_CASE("holonomic: counts and the symbolic Jacobian of the loop") {
  static_assert(loop::m == 2 && kane::degrees_of_freedom<state, loop> == 1);
  static_assert(rates::m == 2 && rates::p == 1 && rates::dependents[0] == 2 && rates::dependents[1] == 3);
  // J = d(f1, f2)/d(q2, q3) = [[-b sin q2, c sin q3], [b cos q2, -c cos q3]]
  state s = start(0.7);
  s.q = {0.7, 0.4, 1.9};
  evaluator ev;
  ev.update(s);
  CHECK(kane::evaluate(loop::jacobian<0, 0>(), ev) == Approx(-lb * std::sin(0.4)));
  CHECK(kane::evaluate(loop::jacobian<0, 1>(), ev) == Approx(lc * std::sin(1.9)));
  CHECK(kane::evaluate(loop::jacobian<1, 0>(), ev) == Approx(lb * std::cos(0.4)));
  CHECK(kane::evaluate(loop::jacobian<1, 1>(), ev) == Approx(-lc * std::cos(1.9)));
}

TEST_CASE("holonomic: Newton closes the loop on the branch of the closed form") {
  for (double q1 : {-2.5, -1.0, 0.0, 0.7, 1.5, 3.0}) {
    state s = start(q1);
    evaluator ev;
    const auto r = kane::solve_configuration<loop>(ev, s);
    REQUIRE(r.status == kane::solve_status::ok);
    CHECK(r.iterations >= 1);
    CHECK(r.iterations <= 8);
    CHECK(r.residual <= 64 * std::numeric_limits<double>::epsilon());
    const auto [q2, q3] = closed_form(q1);
    CHECK(std::remainder(s.q[1] - q2, 2 * M_PI) == Approx(0).margin(1e-12));
    CHECK(std::remainder(s.q[2] - q3, 2 * M_PI) == Approx(0).margin(1e-12));
    CHECK(s.q[0] == q1);  // the independent coordinate is not touched
    for (double f : kane::residuals<kane::configuration<0, 1, dot(gap, e<N, 1>), dot(gap, e<N, 2>)>>(ev))
      CHECK(std::abs(f) < 1e-14);  // ev holds the closed configuration
  }
}

TEST_CASE("holonomic: velocity constraints, A against central differences of solved configurations") {
  const double h = 1e-6;
  for (double q1 : {-1.0, 0.7, 2.0}) {
    state s = start(q1);
    evaluator ev;
    REQUIRE(kane::solve_configuration<loop>(ev, s).status == kane::solve_status::ok);
    const auto sol = kane::solve_constraints<rates>(ev);
    REQUIRE(sol.status == kane::solve_status::ok);
    const auto plus = solved(q1 + h), minus = solved(q1 - h);
    CHECK(sol.A(0, 0) == Approx((plus[0] - minus[0]) / (2 * h)).epsilon(1e-7));
    CHECK(sol.A(1, 0) == Approx((plus[1] - minus[1]) / (2 * h)).epsilon(1e-7));
    CHECK(sol.B(0) == 0);
    // ^N v^Q = v~_1 u1: the nonholonomic partial velocity of the coupler tip against d r^OQ/dq1.
    const auto V = kane::nonholonomic_partial_velocities<N, rates>(kane::velocity<N, Q>(), ev, sol);
    const auto tip = [](double q1_, const std::array<double, 2>& q) {
      return std::array<double, 2>{la * std::cos(q1_) + lb * std::cos(q[0]),
                                   la * std::sin(q1_) + lb * std::sin(q[0])};
    };
    const auto tp = tip(q1 + h, plus), tm = tip(q1 - h, minus);
    CHECK(V(0, 0) == Approx((tp[0] - tm[0]) / (2 * h)).epsilon(1e-7));
    CHECK(V(1, 0) == Approx((tp[1] - tm[1]) / (2 * h)).epsilon(1e-7));
    CHECK(V(2, 0) == 0);
  }
}

TEST_CASE("holonomic: a loop that cannot close, a singular Jacobian, NaN input") {
  evaluator ev;
  SECTION("ground longer than coupler and rocker together: not_converged after max_iterations") {
    state s = start(0.7);
    s.p[3] = 5.0;
    const auto r = kane::solve_configuration<loop>(ev, s, {1e-12, 30});
    CHECK(r.status == kane::solve_status::not_converged);
    CHECK(r.iterations == 30);
    CHECK(r.residual > 1.0);  // at least the gap 5 - (0.3 + 1 + 0.8) remains
  }
  SECTION("coupler along the rocker (q2 = q3): J is singular at the first step") {
    state s = start(0.7);
    s.q = {0.7, 1.0, 1.0};
    const auto r = kane::solve_configuration<loop>(ev, s);
    CHECK(r.status == kane::solve_status::singular);
    CHECK(r.iterations == 0);
    CHECK(s.q[1] == 1.0);
  }
  SECTION("NaN in the state: not_finite, residual NaN") {
    state s = start(0.7);
    s.q[0] = std::nan("");
    const auto r = kane::solve_configuration<loop>(ev, s);
    CHECK(r.status == kane::solve_status::not_finite);
    CHECK(std::isnan(r.residual));
  }
  SECTION("a looser tolerance stops earlier") {
    state s1 = start(0.7), s2 = start(0.7);
    const auto tight = kane::solve_configuration<loop>(ev, s1);
    const auto loose = kane::solve_configuration<loop>(ev, s2, {1e-3, 20});
    CHECK(loose.status == kane::solve_status::ok);
    CHECK(loose.iterations < tight.iterations);
    CHECK(loose.residual <= 1e-3);
  }
}

TEST_CASE("holonomic: the constraint matrix solved, q' as a vector, parameters by their type") {
  state s = start(0.9);
  s[a] = la, s[b] = lb, s[c] = lc, s[d] = ld;  // named parameters address the state
  CHECK(s.p[0] == la);
  CHECK(s[d] == ld);
  evaluator ev;
  REQUIRE(kane::solve_configuration<loop>(ev, s).status == kane::solve_status::ok);
  const auto sol = kane::solve_constraints<rates>(ev);
  REQUIRE(sol.status == kane::solve_status::ok);
  // C u + c0 = 0 with C = df/dq (the velocity constraints of a scleronomic loop): rows n1, n2.
  const double q1 = s.q[0], q2 = s.q[1], q3 = s.q[2];
  CHECK(sol.C(0, 0) == Approx(-la * std::sin(q1)));
  CHECK(sol.C(0, 1) == Approx(-lb * std::sin(q2)));
  CHECK(sol.C(0, 2) == Approx(lc * std::sin(q3)));
  CHECK(sol.C(1, 0) == Approx(la * std::cos(q1)));
  CHECK(sol.C(1, 1) == Approx(lb * std::cos(q2)));
  CHECK(sol.C(1, 2) == Approx(-lc * std::cos(q3)));
  CHECK(sol.c0.norm() == 0);
  const Eigen::Vector3d u(1.0, sol.A(0, 0), sol.A(1, 0));  // u1 = 1 and the dependent speeds
  CHECK((sol.C * u + sol.c0).norm() < 1e-14);
  // q' of the evaluator as one vector: u = q' for qdot_speeds.
  s.u = {0.5, -0.25, 2.0};
  ev.update(s);
  CHECK(ev.coordinate_rates() == s.u);
  kane::evaluator<state, kane::frames<C>, kane::level::acceleration> plain;  // q', q'' from the state
  s.qd = {1, 2, 3}, s.qdd = {4, 5, 6};
  plain.update(s);
  CHECK(plain.coordinate_rates() == s.qd);
  CHECK(plain.coordinate_rates<2>() == s.qdd);
}
