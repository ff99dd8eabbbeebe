// kane::motion is a system for Boost.Odeint as it stands (no adapter): the pendulum of
// models/pendulum3d.hpp by odeint's runge_kutta4 against kane's own use by a hand RK4,
// and a free body with Euler parameters (nq = 7, nu = 6) whose angular momentum about its
// mass centre is conserved (gravity alone, no torque) by odeint's adaptive dopri5.
#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "../examples/models/free_body.hpp"
#include "../examples/models/pendulum3d.hpp"
#include "../examples/rk4.hpp"

namespace {
namespace pd = models::pendulum3d;
namespace fb = models::free_body;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};
using kane::e;
using body_system = kane::system<
    kane::rigid_body<fb::B, fb::Bo, p<4>, kane::inertia<fb::B, fb::Bo, p<5>, p<6>, p<7>, p<8>, p<9>, p<10>>>,
    kane::gravity<-p<11> * e<fb::N, 3>>>;
using body_state = kane::state<double, 7, 6, 11>;
using body_evaluator =
    kane::evaluator<body_state, kane::frames<fb::B>, kane::level::acceleration, fb::speeds>;
}  // namespace

TEST_CASE("odeint: runge_kutta4 over kane::motion is kane's RK4") {
  pd::state s;
  s.p = {1.5,  1.4, 0.9, 1.0,  1.2,   0.7,   0.8,  0.9, 0.07, -0.06, 0.07,
         0.66, 1.2, 1.0, 0.02, -0.03, -0.03, 9.81, 1.5, 0.2,  0.1};
  using rhs = kane::motion<pd::system, pd::evaluator>;
  using vector = std::array<double, rhs::size>;
  vector x = {1.2, -0.7, 0.5, 2.0}, y = x;
  boost::numeric::odeint::integrate_const(boost::numeric::odeint::runge_kutta4<vector>(), rhs(s), x, 0.0, 1.0,
                                          1e-3);
  rhs f(s);
  for (int step = 0; step < 1000; ++step) rk4_step(f, y, step * 1e-3, 1e-3);
  for (std::size_t i = 0; i < x.size(); ++i) CHECK(x[i] == Approx(y[i]).margin(1e-12));
}

TEST_CASE("odeint: a free body keeps its angular momentum about the mass centre") {
  body_state s;
  s.p = {0.2, 0.1, 0.3, 1.3, 0.7, 0.9, 1.1, 0.05, -0.04, 0.08, 9.81};  // a, b, c, m, I.., g
  using rhs = kane::motion<body_system, body_evaluator>;
  std::array<double, rhs::size> x = {1, 0, 0, 0, 0, 0, 0, 0.3, -2.0, 5.0, 1.0, 0.0, 3.0};
  const auto momentum = [&](const std::array<double, rhs::size>& at) {
    body_state b = s;
    for (std::size_t i = 0; i < 7; ++i) b.q[i] = at[i];
    for (std::size_t i = 0; i < 6; ++i) b.u[i] = at[7 + i];
    body_evaluator ev;
    ev.update(b);
    Eigen::Matrix3d i;
    i << 0.7, 0.05, 0.08, 0.05, 0.9, -0.04, 0.08, -0.04, 1.1;  // in B
    const Eigen::Matrix3d c = ev.axes<fb::B>();
    return Eigen::Vector3d(c * (i * Eigen::Vector3d(at[7], at[8], at[9])));
  };
  const Eigen::Vector3d h0 = momentum(x);
  namespace ode = boost::numeric::odeint;
  const auto stepper =
      ode::make_controlled(1e-12, 1e-12, ode::runge_kutta_dopri5<std::array<double, rhs::size>>());
  const std::size_t steps = ode::integrate_adaptive(stepper, rhs(s), x, 0.0, 5.0, 1e-3);
  CHECK(steps > 10);
  CHECK((momentum(x) - h0).norm() < 1e-9 * h0.norm());
  // the mass centre falls freely: w3 = 3 - g t
  CHECK(x[12] == Approx(3.0 - 9.81 * 5.0).epsilon(1e-10));
}
