// Prescribed motion: frames turned and points moved by given functions of time t. A bead on a hoop
// driven about the vertical at phi(t) = Omega t + b sin(c t) against
// theta'' = (phi'^2 cos theta - g / R) sin theta, and a pendulum hung from a cart driven at
// x(t) = a sin(w t) against theta'' = -(g sin theta + x'' cos theta) / L.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>

#include "../examples/rk4.hpp"
#include "trees.hpp"

namespace {
using kane::e;
struct R_ : kane::parameter<1> {};
struct g_ : kane::parameter<2> {};
struct Omega_ : kane::parameter<3> {};
struct b_ : kane::parameter<4> {};
struct c_ : kane::parameter<5> {};
struct m_ : kane::parameter<6> {};
constexpr R_ R;
constexpr g_ g;
constexpr Omega_ Omega;
constexpr b_ b;
constexpr c_ c;
constexpr m_ m;

// The hoop H turns about n3 by phi(t); the bead P sits at angle q1 from the hoop's lowest point.
using trees::N;
struct H
    : kane::frame<N, kane::simple<kane::axis::z, kane::angle<Omega * kane::t + b * kane::sin(c* kane::t)>>> {
};
struct B : kane::frame<H, kane::simple<kane::axis::y, kane::coordinate<1>>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, -R * e<B, 3>> {};
using bead = kane::system<kane::particle<P, m>, kane::gravity<-g * e<N, 3>>>;
using bead_state = kane::state<double, 1, 1, 6>;
using bead_evaluator =
    kane::evaluator<bead_state, kane::frames<B>, kane::level::acceleration, kane::qdot_speeds<1>>;

// theta'' of the closed form at (theta, t) with the parameters of s
double bead_closed(const bead_state& s, double theta, double t) {
  const double phid = s.p[2] + s.p[3] * s.p[4] * std::cos(s.p[4] * t);
  return (phid * phid * std::cos(theta) - s.p[1] / s.p[0]) * std::sin(theta);
}

// A cart at x(t) = a sin(w t) n1 carries a pendulum turning about n3 by q1, its bob at L below.
struct a_ : kane::parameter<3> {};
struct w_ : kane::parameter<4> {};
struct L_ : kane::parameter<5> {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct Cart : kane::point<O, a_{} * kane::sin(w_{} * kane::t) * e<N, 1>> {};
struct Bob : kane::point<Cart, -L_{} * e<A, 2>> {};
using pendulum = kane::system<kane::particle<Bob, m>, kane::gravity<-g * e<N, 2>>>;
using pendulum_state = kane::state<double, 1, 1, 6>;
using pendulum_evaluator =
    kane::evaluator<pendulum_state, kane::frames<A>, kane::level::acceleration, kane::qdot_speeds<1>>;
}  // namespace

TEST_CASE("prescribed motion: a bead on a hoop driven at Omega t + b sin(c t)") {
  bead_state s;
  s.p = {0.5, 9.81, 2.0, 0.3, 1.7, 1.2};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-2.5, 2.5);
  for (int k = 0; k < 10; ++k) {
    s.q = {d(rng)};
    s.u = {d(rng)};
    s.t = d(rng);
    bead_evaluator ev;
    ev.update(s);
    const double exact = bead_closed(s, s.q[0], s.t);
    // Kane's sums, the forward dynamics entry point and an evaluator that reads q' from the state
    const auto [ud, status] = kane::speed_derivatives(kane::mass_matrix_and_forcing<bead>(ev));
    REQUIRE(status == kane::solve_status::ok);
    CHECK(ud(0) == Approx(exact).epsilon(1e-12).margin(1e-12));
    CHECK(kane::forward_dynamics<bead>(ev).ud(0) == Approx(exact).epsilon(1e-12).margin(1e-12));
    bead_state r = s;
    r.qd = {s.u[0]};
    kane::evaluator<bead_state, kane::frames<B>, kane::level::acceleration> by_rates;
    by_rates.update(r);
    CHECK(kane::forward_dynamics<bead>(by_rates).ud(0) == Approx(exact).epsilon(1e-12).margin(1e-12));
    // ^N w^B = phi' n3 + q1' h2: its remainder is the prescribed rate phi' n3
    const kane::vec<N> wt =
        kane::express<N>(kane::velocity_remainder<kane::qdot_speeds<1>>(kane::angular_velocity<N, B>()), ev);
    CHECK(wt[2] == Approx(s.p[2] + s.p[3] * s.p[4] * std::cos(s.p[4] * s.t)).epsilon(1e-14));
    CHECK(std::fabs(wt[0]) + std::fabs(wt[1]) == 0.0);
  }
  // kane::motion over 2 s by RK4: theta'' at every step is the closed form's at the step's t
  kane::motion<bead, bead_evaluator> rhs(s);
  std::array<double, 2> x{0.4, 0.0}, dx{};
  const double h = 1e-3;
  for (int k = 0; k < 2000; ++k) {
    const double t = k * h;
    rhs(x, dx, t);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    CHECK(dx[1] == Approx(bead_closed(s, x[0], t)).epsilon(1e-12).margin(1e-12));
    rk4_step(rhs, x, t, h);
  }
}

TEST_CASE("prescribed motion: a pendulum hung from a cart driven at a sin(w t)") {
  pendulum_state s;
  s.p = {0.0, 9.81, 0.2, 3.0, 0.8, 1.5};
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> d(-2.5, 2.5);
  for (int k = 0; k < 10; ++k) {
    s.q = {d(rng)};
    s.u = {d(rng)};
    s.t = d(rng);
    pendulum_evaluator ev;
    ev.update(s);
    const auto [ud, status] = kane::speed_derivatives(kane::mass_matrix_and_forcing<pendulum>(ev));
    REQUIRE(status == kane::solve_status::ok);
    const double xdd = -s.p[2] * s.p[3] * s.p[3] * std::sin(s.p[3] * s.t);
    const double exact = -(s.p[1] * std::sin(s.q[0]) + xdd * std::cos(s.q[0])) / s.p[4];
    CHECK(ud(0) == Approx(exact).epsilon(1e-12).margin(1e-12));
    CHECK(kane::forward_dynamics<pendulum>(ev).ud(0) == Approx(exact).epsilon(1e-12).margin(1e-12));
  }
}
