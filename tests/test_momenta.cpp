// Momenta and energies (dynamics/momenta.hpp): against SymPy's angular momentum and
// potential energy (tests/data/gen_dynamics.py), closed forms, and their conservation
// along RK4 runs of free systems.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include <kane/kane.hpp>

#include "../examples/rk4.hpp"
#include "sympy_states.hpp"

namespace {
using kane::e;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};
namespace pd = models::pendulum3d;
namespace fm = models::free_body;

// SymPy's free body (test_dynamics.cpp): m p4, inertia p5..p10 about Bo in B, gravity p11.
using body =
    kane::rigid_body<fm::B, fm::Bo, p<4>, kane::inertia<fm::B, fm::Bo, p<5>, p<6>, p<7>, p<8>, p<9>, p<10>>>;
using free_system = kane::system<body, kane::gravity<-p<11> * e<fm::N, 3>>>;
using body_state = kane::state<double, 7, 6, 17>;
using body_evaluator =
    kane::evaluator<body_state, kane::frames<fm::B>, kane::level::acceleration, fm::speeds>;

}  // namespace

TEST_CASE("momenta: a free body's momenta against SymPy and the transfer to another point") {
  for (const auto& x : sympy_dynamics::body) {
    const body_state s = sympy_states::free_body(x);
    body_evaluator ev;
    ev.update(s);
    const double m = s.p[3];
    const Eigen::Vector3d v(x.u[3], x.u[4], x.u[5]), r(x.q[3], x.q[4], x.q[5]);
    const Eigen::Vector3d h(x.H_N[0], x.H_N[1], x.H_N[2]);
    const kane::vec<fm::N> p = kane::linear_momentum<free_system>(ev);
    CHECK((p.eigen() - m * v).norm() < 1e-14 * m * v.norm());
    const kane::vec<fm::N> hg = kane::angular_momentum<free_system>(ev);
    CHECK((hg.eigen() - h).norm() < 1e-14 * h.norm());
    CHECK((kane::angular_momentum<free_system, fm::Bo>(ev).eigen() - h).norm() < 1e-14 * h.norm());
    // H^O = H^Bo + r^OBo x m v^Bo
    const Eigen::Vector3d ho = h + r.cross(m * v);
    CHECK((kane::angular_momentum<free_system, fm::O>(ev).eigen() - ho).norm() < 1e-14 * ho.norm());
    CHECK(kane::kinetic_energy<free_system>(ev) == Approx(x.T).epsilon(1e-14));
    // V = m g z, zero at O; zero at Bo
    CHECK(kane::potential_energy<free_system>(ev) == Approx(m * s.p[10] * x.q[5]).epsilon(1e-14));
    CHECK(kane::potential_energy<free_system, fm::Bo>(ev) == 0.0);
  }
}

TEST_CASE("momenta: the 3D double pendulum's potential energy against SymPy's") {
  for (const auto& x : sympy_dynamics::pendulum) {
    const pd::state s = sympy_states::pendulum(x);
    pd::evaluator ev;
    ev.update(s);
    // SymPy's V adds the torsion spring k q2^2 / 2, which is a torque load here
    const double spring = s.p[18] * x.q[1] * x.q[1] / 2;
    CHECK(kane::potential_energy<pd::system>(ev) + spring == Approx(x.V).epsilon(1e-14));
    // zero at the joint J: V^J = V^O - m_total g . r^OJ = V^O + m_total g z_J
    const double mass = s.p[2] + s.p[3] + s.p[4], zj = -s.p[0] * std::cos(x.q[0]);
    CHECK(kane::potential_energy<pd::system, pd::J>(ev) ==
          Approx(kane::potential_energy<pd::system>(ev) - mass * s.p[17] * zj).epsilon(1e-13));
  }
}

TEST_CASE("momenta: a tumbling free body keeps its momenta over an RK4 run") {
  using gravity_free = kane::system<body>;
  using rhs = kane::motion<gravity_free, body_evaluator>;
  body_state s;
  s.p = {0, 0, 0, 1.3, 0.7, 0.9, 1.1, 0.05, -0.04, 0.08, 0};
  rhs f(s);
  std::array<double, rhs::size> x = {1, 0, 0, 0, 0.1, -0.2, 0.3, 0.3, -2.0, 5.0, 1.0, 0.5, -0.7};
  const auto momenta = [&] {
    body_state b = s;
    for (std::size_t i = 0; i < 7; ++i) b.q[i] = x[i];
    for (std::size_t i = 0; i < 6; ++i) b.u[i] = x[7 + i];
    body_evaluator ev;
    ev.update(b);
    return std::array<Eigen::Vector3d, 3>{kane::linear_momentum<gravity_free>(ev).eigen(),
                                          kane::angular_momentum<gravity_free>(ev).eigen(),
                                          kane::angular_momentum<gravity_free, fm::O>(ev).eigen()};
  };
  const auto m0 = momenta();
  for (int k = 0; k < 2000; ++k) rk4_step(f, x, 1e-3 * k, 1e-3);
  REQUIRE(f.status() == kane::solve_status::ok);
  const auto m1 = momenta();
  for (int i = 0; i < 3; ++i) CHECK((m1[i] - m0[i]).norm() < 1e-12 * m0[i].norm());
  // the body turned: H^O is constant in N, not in B
  CHECK(std::abs(x[0] - 1.0) > 0.1);
}

TEST_CASE("momenta: an undamped 3D double pendulum keeps T + V over an RK4 run") {
  using rhs = kane::motion<pd::system, pd::evaluator>;
  pd::state s;
  for (int i = 0; i < 21; ++i) s.p[i] = sympy_dynamics::pendulum_p[i];
  s.p[18] = s.p[19] = s.p[20] = 0;  // no spring, damper or drag
  rhs f(s);
  std::array<double, rhs::size> x = {0.9, -0.6, 1.5, 2.0};
  const auto energy = [&] {
    pd::state b = s;
    b.q = {x[0], x[1]};
    b.u = {x[2], x[3]};
    pd::evaluator ev;
    ev.update(b);
    return kane::kinetic_energy<pd::system>(ev) + kane::potential_energy<pd::system>(ev);
  };
  const double e0 = energy();
  for (int k = 0; k < 4000; ++k) rk4_step(f, x, 5e-4 * k, 5e-4);  // RK4 keeps T + V to O(h^4)
  REQUIRE(f.status() == kane::solve_status::ok);
  INFO("T + V = " << e0 << ", drift " << energy() - e0);
  CHECK(std::abs(energy() - e0) < 1e-12 * std::abs(e0));
}

namespace {
// Springs: a particle on a spring from a fixed point under gravity (beside a falling one), and two
// particles joined by a spring, free in space; k = p1, L = p2, masses p3 (and p4), g = p5.
namespace springs {
using kane::e;
struct N : kane::root_frame {};
struct O : kane::origin<N> {};
struct P : kane::point<O, kane::q<1> * e<N, 1> + kane::q<2> * e<N, 2> + kane::q<3> * e<N, 3>> {};
struct Q : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2> + kane::q<6> * e<N, 3>> {};
using hanging = kane::system<kane::particle<P, p<3>>, kane::particle<Q, p<4>>, kane::spring<O, P, p<1>, p<2>>,
                             kane::gravity<-p<5> * e<N, 3>>>;  // Q falls freely
using pair = kane::system<kane::particle<P, p<3>>, kane::particle<Q, p<4>>, kane::spring<P, Q, p<1>, p<2>>>;
}  // namespace springs
}  // namespace

TEST_CASE("springs: the forces of a spring and its potential energy against the closed form") {
  namespace sp = springs;
  kane::state<double, 6, 6, 5> s;
  s.q = {0.3, -0.4, -1.2, 1.1, 0.5, -0.2};
  s.u = {0.7, 0.1, -0.3, -0.2, 0.4, 0.9};
  s.p = {40.0, 0.8, 1.5, 2.5, 9.81};
  kane::evaluator<decltype(s), kane::frames<sp::N>, kane::level::acceleration, kane::qdot_speeds<6>> ev;
  ev.update(s);
  const double k = s.p[0], L = s.p[1], m = s.p[2], mq = s.p[3], g = s.p[4];
  const Eigen::Vector3d rp(s.q[0], s.q[1], s.q[2]), rq(s.q[3], s.q[4], s.q[5]);
  // hanging: m r'' = -k (|r| - L) r / |r| - m g n3; V = k (|r| - L)^2 / 2 + m g r . n3 (+ Q's)
  const auto e1 = kane::mass_matrix_and_forcing<sp::hanging>(ev);
  REQUIRE(e1.status == kane::solve_status::ok);
  const Eigen::Vector3d f1 = -k * (rp.norm() - L) * rp.normalized() - m * g * Eigen::Vector3d::UnitZ();
  for (int i = 0; i < 3; ++i) {
    CHECK(e1.f(i) == Approx(f1(i)).epsilon(1e-14));
    CHECK(e1.M(i, i) == Approx(m).epsilon(1e-15));
  }
  CHECK(e1.f(3) == 0);
  CHECK(e1.f(4) == 0);
  CHECK(e1.f(5) == Approx(-mq * g).epsilon(1e-15));
  CHECK(kane::potential_energy<sp::hanging>(ev) ==
        Approx(k * (rp.norm() - L) * (rp.norm() - L) / 2 + m * g * rp.z() + mq * g * rq.z()).epsilon(1e-14));
  // the pair: equal and opposite forces along r^PQ
  const auto e2 = kane::mass_matrix_and_forcing<sp::pair>(ev);
  REQUIRE(e2.status == kane::solve_status::ok);
  const Eigen::Vector3d r = rq - rp, f2 = k * (r.norm() - L) * r.normalized();  // on P
  for (int i = 0; i < 3; ++i) {
    CHECK(e2.f(i) == Approx(f2(i)).epsilon(1e-14));
    CHECK(e2.f(3 + i) == Approx(-f2(i)).epsilon(1e-14));
    CHECK(e2.M(3 + i, 3 + i) == Approx(mq).epsilon(1e-15));
  }
  CHECK(kane::potential_energy<sp::pair>(ev) ==
        Approx(k * (r.norm() - L) * (r.norm() - L) / 2).epsilon(1e-14));
}

TEST_CASE("springs: a hanging spring keeps T + V, a free pair its momentum and T + V, over RK4 runs") {
  namespace sp = springs;
  using St = kane::state<double, 6, 6, 5>;
  using Ev = kane::evaluator<St, kane::frames<sp::N>, kane::level::acceleration, kane::qdot_speeds<6>>;
  St s;
  s.p = {40.0, 0.8, 1.5, 2.5, 9.81};
  const auto run = [&]<class Sys>(std::type_identity<Sys>) {
    kane::motion<Sys, Ev> f(s);
    std::array<double, 12> x = {0.3, -0.4, -1.2, 1.1, 0.5, -0.2, 0.7, 0.1, -0.3, -0.2, 0.4, 0.9};
    const auto at = [&] {
      St b = s;
      for (int i = 0; i < 6; ++i) b.q[i] = x[i], b.u[i] = x[6 + i];
      Ev ev;
      ev.update(b);
      return std::pair{kane::kinetic_energy<Sys>(ev) + kane::potential_energy<Sys>(ev),
                       Eigen::Vector3d(kane::linear_momentum<Sys>(ev).eigen())};
    };
    const auto [e0, p0] = at();
    for (int k = 0; k < 4000; ++k) rk4_step(f, x, 5e-4 * k, 5e-4);
    REQUIRE(f.status() == kane::solve_status::ok);
    const auto [e1, p1] = at();
    INFO("T + V = " << e0 << ", drift " << e1 - e0);
    CHECK(std::abs(e1 - e0) < 1e-10 * std::abs(e0));
    return (p1 - p0).norm();
  };
  run(std::type_identity<sp::hanging>{});
  CHECK(run(std::type_identity<sp::pair>{}) < 1e-12);
}
