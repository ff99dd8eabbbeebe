// Linearization of a closed loop (linearization/linearize.hpp): the four-bar with a crank
// torque as input. The dependent coordinates' jets come from the loop's partial derivatives
// on numbers, or, with an input, from a Newton step on jets: both A agree, and A and B agree
// with central differences of the nonlinear right-hand side with the loop closed again.
// (Its own unit: beside test_linearize.cpp one compile would peak at 2.2 GB.)
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <limits>

#include <kane/linearization.hpp>

#include "../examples/models/fourbar.hpp"
#include "../examples/rk4.hpp"

namespace {
namespace fb = models::fourbar;
// The four-bar with masses at the crank tip P (as a body of frame A, so that the crank
// torque T acts on it) and at the coupler tip Q, gravity -g n2, T = p5 about n3.
// p1..p4 the lengths a, b, c, d; p5 T, p6 m_P, p7 m_Q, p8 g, p9 the crank's I33 about P.
template <std::size_t I>
inline constexpr kane::parameter<I> fp{};
using fourbar_system =
    kane::system<kane::rigid_body<fb::A, fb::P, fp<6>, kane::inertia<fb::A, fb::P, fp<9>, fp<9>, fp<9>>>,
                 kane::particle<fb::Q, fp<7>>, kane::gravity<-fp<8> * kane::e<fb::N, 2>>,
                 kane::torque<fb::A, fp<5> * kane::e<fb::N, 3>>>;
using fourbar_state = kane::state<double, 3, 3, 9>;
using fourbar_evaluator =
    kane::evaluator<fourbar_state, kane::frames<fb::A, fb::B, fb::C>, kane::level::acceleration, fb::speeds>;

// x' = (q1', q2', q3', u1') of the four-bar at q1, u1 with the loop closed from a guess.
std::array<double, 4> fourbar_rate(fourbar_state s) {
  fourbar_evaluator ev;
  REQUIRE(kane::solve_configuration<fb::loop>(ev, s).status == kane::solve_status::ok);
  kane::constrained_motion<fourbar_system, fb::rates, fourbar_evaluator> f(s);
  std::array<double, 4> x{s.q[0], s.q[1], s.q[2], s.u[0]}, dx;
  f(x, dx, 0.0);
  return dx;
}
// The four-bar at the crank angle 0.9 and rate u1, the loop closed (q2, q3 from a guess).
fourbar_state closed_fourbar(double u1) {
  fourbar_state s;
  s.p = {1.0, 2.2, 1.8, 2.5, 0.7, 1.3, 0.9, 9.81, 0.05};
  s.q = {0.9, 0.6, 1.9};
  s.u = {u1, 0, 0};
  fourbar_evaluator ev;
  REQUIRE(kane::solve_configuration<fb::loop>(ev, s).status == kane::solve_status::ok);
  return s;
}
}  // namespace

TEST_CASE("linearize: a closed loop (four-bar) with and without an input, against central differences") {
  fourbar_state s = closed_fourbar(0.8);
  // x = (q1, u1): q2, q3 from the loop (one pass on numbers, or a Newton step on jets with an input)
  const auto lin = kane::linearize_constrained<fourbar_system, fb::rates, fourbar_evaluator, fb::loop>(s);
  const auto lin_t = kane::linearize_constrained<fourbar_system, fb::rates, fourbar_evaluator, fb::loop,
                                                 kane::inputs<fp<5>>>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  REQUIRE(lin_t.status == kane::solve_status::ok);
  CHECK((lin.A - lin_t.A).cwiseAbs().maxCoeff() < 1e-12 * lin.A.cwiseAbs().maxCoeff());
  const double h = 1e-5;
  for (int j = 0; j < 3; ++j) {  // q1, u1, T
    CAPTURE(j);
    fourbar_state plus = s, minus = s;
    (j == 0 ? plus.q[0] : j == 1 ? plus.u[0] : plus.p[4]) += h;
    (j == 0 ? minus.q[0] : j == 1 ? minus.u[0] : minus.p[4]) -= h;
    const auto up = fourbar_rate(plus), down = fourbar_rate(minus);
    const int rows[2] = {0, 3};  // q1', u1'
    for (int i = 0; i < 2; ++i) {
      const double fd = (up[std::size_t(rows[i])] - down[std::size_t(rows[i])]) / (2 * h);
      const double exact = j < 2 ? lin.A(i, j) : lin_t.B(i, 0);
      CHECK(exact == Approx(fd).margin(1e-8).epsilon(1e-7));
    }
  }
  CHECK(lin_t.B(1, 0) != 0);  // the torque accelerates the crank

  s.p[0] = std::numeric_limits<double>::quiet_NaN();  // a NaN crank length, on both paths
  CHECK(kane::linearize_constrained<fourbar_system, fb::rates, fourbar_evaluator, fb::loop>(s).status ==
        kane::solve_status::not_finite);
  CHECK(kane::linearize_constrained<fourbar_system, fb::rates, fourbar_evaluator, fb::loop,
                                    kane::inputs<fp<5>>>(s)
            .status == kane::solve_status::not_finite);
}

TEST_CASE("constrained_motion: project closes the loop that integration lets drift") {
  fourbar_state s = closed_fourbar(2.0);
  kane::constrained_motion<fourbar_system, fb::rates, fourbar_evaluator> f(s);
  const auto gap = [&](const std::array<double, 4>& x) {  // max |f_k| of the loop at x's q
    fourbar_state t = s;
    t.q = {x[0], x[1], x[2]};
    fourbar_evaluator e;
    e.update(t);
    return std::fmax(std::fabs(kane::evaluate(kane::dot(fb::gap, kane::e<fb::N, 1>), e)),
                     std::fabs(kane::evaluate(kane::dot(fb::gap, kane::e<fb::N, 2>), e)));
  };
  std::array<double, 4> drifting{s.q[0], s.q[1], s.q[2], s.u[0]}, projected = drifting;
  const double h = 0.05;
  for (int k = 0; k < 40; ++k) {
    rk4_step(f, drifting, k * h, h);
    rk4_step(f, projected, k * h, h);
    const auto closed = f.project<fb::loop>(projected);
    REQUIRE(closed.status == kane::solve_status::ok);
    CHECK(closed.residual <= 64 * std::numeric_limits<double>::epsilon());
  }
  CHECK(gap(projected) < 1e-13);
  CHECK(gap(drifting) > 1e-8);                          // RK4 keeps the loop's rates, not the loop
  CHECK(std::fabs(projected[0] - drifting[0]) < 1e-4);  // the crank angle moves as before
  // a run-time size other than nq + p: wrong_size, x unchanged
  Eigen::VectorXd three = Eigen::VectorXd::Constant(3, 0.5);
  CHECK(f.project<fb::loop>(three).status == kane::solve_status::wrong_size);
  CHECK((three.array() == 0.5).all());
}

TEST_CASE("linearize: the four-bar's directions one at a time: A, and the second-order form") {
  fourbar_state s = closed_fourbar(0.8);
  using In = kane::inputs<fp<5>>;
  namespace kd = kane::detail;
  const auto near = [](const auto& a, const auto& b) {
    return (a - b).cwiseAbs().maxCoeff() <= 1e-13 * (1 + b.cwiseAbs().maxCoeff());
  };
  // without an input the dependent coordinates' jets come from the loop's partial derivatives
  const auto all = kane::linearize_constrained<fourbar_system, fb::rates, fourbar_evaluator, fb::loop>(s);
  const auto one =
      kd::constrained_in_batches<fourbar_system, fb::rates, fourbar_evaluator, fb::loop, kane::inputs<>, 1>(
          s);
  REQUIRE(one.status == kane::solve_status::ok);
  CHECK(near(one.A, all.A));
  CHECK(near(one.rate, all.rate));
  // the second-order form with an input, one direction a batch: M du'/dx = -(K C) gives the row of
  // u1 in A, and M du'/dr = B the central difference of u1' by the torque
  const auto eq = kd::equations_in_batches<fourbar_system, fb::rates, fourbar_evaluator, fb::loop, In, 1>(s);
  REQUIRE(eq.status == kane::solve_status::ok);
  const double m = eq.M(0, 0), h = 1e-5;
  CHECK(-eq.K(0, 0) / m == Approx(all.A(1, 0)).epsilon(1e-12));
  CHECK(-eq.C(0, 0) / m == Approx(all.A(1, 1)).epsilon(1e-12));
  fourbar_state plus = s, minus = s;
  plus.p[4] += h, minus.p[4] -= h;
  CHECK(eq.B(0, 0) / m ==
        Approx((fourbar_rate(plus)[3] - fourbar_rate(minus)[3]) / (2 * h)).margin(1e-8).epsilon(1e-7));
  CHECK(eq.B(0, 0) != 0);
}
