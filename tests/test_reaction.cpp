// Noncontributing forces by auxiliary speeds (dynamics/reaction.hpp) against Newton-Euler written by
// hand on kane's own accelerations: the pin reaction of a planar double pendulum and the contact force
// of the rolling disc, along trajectories integrated by RK4.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "../examples/models/disc.hpp"
#include "../examples/rk4.hpp"
#include "trees.hpp"

namespace {
using kane::e;
// A about n3 by q1, B about a3 by q2; particles m1 at P1 = L1 a1, m2 at P2 = P1 + L2 b1; gravity g n1.
struct L1 : kane::parameter<1> {};
struct L2 : kane::parameter<2> {};
struct m1 : kane::parameter<3> {};
struct m2 : kane::parameter<4> {};
struct g_ : kane::parameter<5> {};
using trees::N;
struct A : kane::frame<N, kane::simple<kane::axis::z, trees::q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::z, trees::q2>> {};
struct O : kane::origin<N> {};
struct P1 : kane::point<O, L1{} * e<A, 1>> {};
struct P2 : kane::point<P1, L2{} * e<B, 1>> {};
using pendulum =
    kane::system<kane::particle<P1, m1{}>, kane::particle<P2, m2{}>, kane::gravity<g_{} * e<N, 1>>>;
using pendulum_state = kane::state<double, 2, 2, 5>;
using pendulum_evaluator =
    kane::evaluator<pendulum_state, kane::frames<B>, kane::level::acceleration, kane::qdot_speeds<2>>;

// The acceleration of L cos(th) n1 + L sin(th) n2 with th' and th''.
Eigen::Vector2d circling(double l, double th, double thd, double thdd) {
  const double c = std::cos(th), s = std::sin(th);
  return {l * (-s * thdd - c * thd * thd), l * (c * thdd - s * thd * thd)};
}

namespace dd = models::disc;
using disc_state = kane::state<double, 5, 5, 3>;
using disc_evaluator =
    kane::evaluator<disc_state, kane::frames<dd::R>, kane::level::acceleration, dd::speeds5>;
}  // namespace

TEST_CASE("reaction: a double pendulum's pin reactions against Newton-Euler") {
  pendulum_state s;
  s.p = {1.1, 0.7, 2.0, 1.5, 9.81};
  kane::motion<pendulum, pendulum_evaluator> rhs(s);
  std::array<double, 4> x{0.9, -0.4, 0.3, 1.2}, dx{};
  const double h = 1e-3, l1 = s.p[0], l2 = s.p[1], ma = s.p[2], mb = s.p[3], g = s.p[4];
  for (int k = 0; k < 1000; ++k) {
    rhs(x, dx, k * h);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    if (k % 50 == 0) {
      // the state with the motion's u'
      s.q = {x[0], x[1]}, s.u = {x[2], x[3]}, s.ud = {dx[2], dx[3]};
      pendulum_evaluator ev;
      ev.update(s);
      const auto pin = kane::reaction<pendulum, kane::cut<P1, P2>>(ev);        // on the lower particle
      const auto ground = kane::reaction<pendulum, kane::cut<O, P1, P2>>(ev);  // on both, at O
      REQUIRE(pin.status == kane::solve_status::ok);
      // Newton on m2 and on both: R = sum m (a - g n1), a by hand from q, q', q''
      const Eigen::Vector2d a1 = circling(l1, s.q[0], s.u[0], s.ud[0]);
      const Eigen::Vector2d a2 = a1 + circling(l2, s.q[0] + s.q[1], s.u[0] + s.u[1], s.ud[0] + s.ud[1]);
      const Eigen::Vector2d gn(g, 0);
      const Eigen::Vector2d r2 = mb * (a2 - gn), r12 = ma * (a1 - gn) + r2;
      CHECK(std::fabs(pin.force[0] - r2(0)) + std::fabs(pin.force[1] - r2(1)) < 1e-12 * (1 + r2.norm()));
      CHECK(std::fabs(ground.force[0] - r12(0)) + std::fabs(ground.force[1] - r12(1)) <
            1e-12 * (1 + r12.norm()));
      CHECK(pin.force[2] == 0.0);
      // frictionless pins: no moment about them
      CHECK(std::fabs(pin.moment[0]) + std::fabs(pin.moment[1]) + std::fabs(pin.moment[2]) <
            1e-12 * r2.norm());
      CHECK(std::fabs(ground.moment[2]) < 1e-12 * r12.norm());
    }
    rk4_step(rhs, x, k * h, h);
  }
}

TEST_CASE("reaction: the rolling disc's contact force against Newton's law, no contact moment") {
  disc_state s;
  s.p = {0.3, 1.7, 9.81};
  kane::constrained_motion<dd::system, dd::rolling, disc_evaluator> rhs(s);
  std::array<double, 8> x{0.2, 0.35, 0.1, 0.5, -0.3, 0.4, 5.0, 1.1}, dx{};  // q1..q5, u1..u3
  const double h = 1e-3, r = s.p[0], m = s.p[1], g = s.p[2];
  for (int k = 0; k < 1000; ++k) {
    rhs(x, dx, k * h);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    if (k % 50 == 0) {
      // u and u' of all five speeds: u' = T u_ind' + b from the reduced equations
      s = rhs.state();
      disc_evaluator ev;
      ev.update(s);
      const auto sol = kane::solve_constraints<dd::rolling>(ev);
      const auto eq = kane::reduced_mass_matrix_and_forcing<dd::system, dd::rolling>(ev, sol);
      const Eigen::Matrix<double, 5, 1> ud = eq.T * Eigen::Vector3d(dx[5], dx[6], dx[7]) + eq.b;
      for (std::size_t i = 0; i < 5; ++i) s.ud[i] = ud(Eigen::Index(i));
      ev.update(s);
      REQUIRE(ev.status() == kane::solve_status::ok);
      const auto contact = kane::reaction<dd::system, kane::cut<dd::Below, dd::R>>(ev);
      REQUIRE(contact.status == kane::solve_status::ok);
      // Newton: R = m (a + g n3), a of the centre (q4 + r s1 s2, q5 - r c1 s2, r c2) by hand
      const auto qd = ev.coordinate_rates(), qdd = ev.coordinate_rates<2>();
      const double s1 = std::sin(s.q[0]), c1 = std::cos(s.q[0]), s2 = std::sin(s.q[1]), c2 = std::cos(s.q[1]);
      const double w1 = qd[0], w2 = qd[1], w1d = qdd[0], w2d = qdd[1];
      const Eigen::Vector3d a(qdd[3] + r * (-s1 * s2 * (w1 * w1 + w2 * w2) + 2 * c1 * c2 * w1 * w2 +
                                            c1 * s2 * w1d + s1 * c2 * w2d),
                              qdd[4] - r * (-c1 * s2 * (w1 * w1 + w2 * w2) - 2 * s1 * c2 * w1 * w2 -
                                            s1 * s2 * w1d + c1 * c2 * w2d),
                              -r * (c2 * w2 * w2 + s2 * w2d));
      const Eigen::Vector3d newton = m * (a + Eigen::Vector3d(0, 0, g));
      CHECK((contact.force.eigen() - newton).norm() < 1e-12 * newton.norm());
      // a point contact: no moment about it
      CHECK(contact.moment.eigen().norm() < 1e-12 * m * g * r);
    }
    rk4_step(rhs, x, k * h, h);
  }
}
