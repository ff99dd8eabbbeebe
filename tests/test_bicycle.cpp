// The kinematics of the Whipple bicycle (examples/models/bicycle.hpp) against SymPy's
// model of test_bicycle (tests/data/gen_bicycle.py): the pitch that closes the front
// contact, the dependent speeds of the velocity constraints, the nonholonomic partial
// velocities of both wheel centres and the partial angular velocities of the rear
// frame and the fork. SymPy's speeds (u2 roll, u3 rear wheel, u5 steer | u1 yaw,
// u4 pitch, u6 front wheel) are kane's (u4, u7, u6 | u3, u5, u8).
#include <catch2/catch.hpp>
#include <cmath>

#include "../examples/models/bicycle.hpp"
#include "data/sympy_bicycle.hpp"

namespace {
using namespace models::bicycle;
using sympy_bicycle::samples;

// kane's independent speeds (u4, u6, u7) in SymPy's order (u2, u3, u5): columns 0, 2, 1
constexpr int column_of[3] = {0, 2, 1};

double table_diff(const Eigen::Matrix<double, 3, 3>& kane_columns, const double (&sympy)[3][3]) {
  double d = 0;
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(kane_columns(i, column_of[r]) - sympy[r][i]));
  return d;
}

state configured(const sympy_bicycle::sample& x) {
  const auto& p = sympy_bicycle::params;
  state s;
  s.p = {p.WFrad, p.WRrad, p.htangle, p.forkoffset, p.forklength, p.framelength};
  s.q = {0.7, -1.3, x.yaw, x.roll, 0.0, x.steer};  // the pitch from 0 by Newton's method
  return s;
}
}  // namespace

TEST_CASE("bicycle: pitch, dependent speeds and nonholonomic partial velocities against SymPy") {
  for (const auto& x : samples) {
    state s = configured(x);
    evaluator ev;
    const auto closed = kane::solve_configuration<pitch>(ev, s);
    REQUIRE(closed.status == kane::solve_status::ok);
    CHECK(closed.iterations <= 5);
    CHECK(s.q[4] == Approx(x.pitch).margin(1e-14));
    const auto sol = kane::solve_constraints<rolling>(ev);
    REQUIRE(sol.status == kane::solve_status::ok);
    // rows u3 (yaw), u5 (pitch), u8 (front wheel) of A are SymPy's rows u1, u4, u6
    for (int dep = 0; dep < 3; ++dep)
      for (int r = 0; r < 3; ++r) CHECK(sol.A(2 + dep, column_of[r]) == Approx(x.A[dep][r]).margin(1e-13));
    const auto v_rear = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Dr>(), ev, sol);
    const auto v_front = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Df>(), ev, sol);
    const auto w_frame =
        kane::nonholonomic_partial_velocities<N, rolling>(kane::angular_velocity<N, H>(), ev, sol);
    const auto w_fork =
        kane::nonholonomic_partial_velocities<N, rolling>(kane::angular_velocity<N, F>(), ev, sol);
    CHECK(table_diff(v_rear, x.v_rear) < 1e-14);
    CHECK(table_diff(v_front, x.v_front) < 1e-14);
    CHECK(table_diff(w_frame, x.w_frame) < 1e-14);
    CHECK(table_diff(w_fork, x.w_fork) < 1e-14);
  }
}

TEST_CASE("bicycle: with the dependent speeds solved, both wheels roll and the front stays on the ground") {
  for (const auto& x : samples) {
    state s = configured(x);
    evaluator ev;
    REQUIRE(kane::solve_configuration<pitch>(ev, s).status == kane::solve_status::ok);
    const auto sol = kane::solve_constraints<rolling>(ev);
    const Eigen::Vector3d independent(0.3, -0.8, 6.0);  // roll, steer, rear wheel rates
    const Eigen::Matrix<double, 5, 1> dependent = sol.A * independent;
    constexpr int dep[5] = {0, 1, 2, 4, 7}, ind[3] = {3, 5, 6};
    for (int i = 0; i < 5; ++i) s.u[dep[i]] = dependent(i);
    for (int i = 0; i < 3; ++i) s.u[ind[i]] = independent(i);
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    CHECK(kane::express<N>(v_br, ev).eigen().norm() < 1e-14);
    CHECK(kane::express<N>(v_bf, ev).eigen().norm() < 1e-14);
    CHECK(std::abs(kane::evaluate(kane::dt(ground), ev)) < 1e-15);
    // the rear contact moves with rr (u5 + u7) y1: the wheel turns relative to R about r2 = h2
    const double rate = s.p[1] * (s.u[4] + s.u[6]);
    CHECK(s.u[0] == Approx(rate * std::cos(x.yaw)).margin(1e-14));
    CHECK(s.u[1] == Approx(rate * std::sin(x.yaw)).margin(1e-14));
  }
}
