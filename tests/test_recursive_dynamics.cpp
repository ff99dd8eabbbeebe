// Kane's equations regrouped over the tree (composite bodies, inward sums,
// articulated bodies) against a second method: Newton-Euler written by hand for
// the 6R arm, Kane's sums over the partial velocities for a tree with branches,
// fixed rotations, a particle, a force and torques, and for a floating base on a free joint
// carrying two arms, and M^-1 f for a 21-link chain.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include <Eigen/Cholesky>
#include <kane/kane.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "differences.hpp"
#include "floating_arms.hpp"
#include "recursive_models.hpp"

namespace {
using kane::e;
using kane::literal;

// The 6R arm with masses and joint torques as inputs (examples/models/arm6_dynamics.hpp).
namespace arm {
using namespace models::arm6;
using system = links;
const auto& L = length;
using state = kane::state<double, 6>;
using evaluator = kane::evaluator<state, kane::frames<B6>, kane::level::acceleration, kane::qdot_speeds<6>>;
using driven_state = kane::state<double, 6, 6, 0, 6>;
using driven_evaluator =
    kane::evaluator<driven_state, kane::frames<B6>, kane::level::acceleration, kane::qdot_speeds<6>>;

// Newton-Euler by hand, in N: outward w, alpha, a of the joints and centres; inward
// F_i = f_i + F_{i+1}, N_i = n_i + (c_i - p_i) x f_i + N_{i+1} + (p_{i+1} - p_i) x F_{i+1};
// tau_i = z_i . N_i.
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
Eigen::Matrix<double, 6, 1> newton_euler(const double* q, const double* qd, const double* qdd) {
  constexpr int axis[6] = {2, 1, 1, 0, 1, 0};
  M3 R = M3::Identity();
  V3 w = V3::Zero(), al = V3::Zero(), a = V3(0, 0, g), p = V3::Zero();  // gravity: the base accelerates up
  V3 z[6], pos[7], cm[6], f[6], n[6];
  for (int i = 0; i < 6; ++i) {
    z[i] = R.col(axis[i]);
    const V3 w0 = w;
    w = w0 + qd[i] * z[i];
    al = al + qdd[i] * z[i] + qd[i] * w0.cross(z[i]);
    R = R * Eigen::AngleAxisd(q[i], V3::Unit(axis[i])).toRotationMatrix();
    const V3 x = R.col(0);
    pos[i] = p;
    cm[i] = p + 0.5 * L[i] * x;
    const V3 ac = a + al.cross(0.5 * L[i] * x) + w.cross(w.cross(0.5 * L[i] * x));
    a = a + al.cross(L[i] * x) + w.cross(w.cross(L[i] * x));
    p = p + L[i] * x;
    const double* j = inertia[i];
    M3 ib;
    ib << j[0], j[3], j[5], j[3], j[1], j[4], j[5], j[4], j[2];
    const M3 iw = R * ib * R.transpose();
    f[i] = mass[i] * ac;
    n[i] = iw * al + w.cross(iw * w);
  }
  pos[6] = p;
  Eigen::Matrix<double, 6, 1> tau;
  V3 F = V3::Zero(), Nm = V3::Zero();
  for (int i = 5; i >= 0; --i) {
    Nm = n[i] + (cm[i] - pos[i]).cross(f[i]) + Nm + (pos[i + 1] - pos[i]).cross(F);
    F = f[i] + F;
    tau(i) = z[i].dot(Nm);
  }
  return tau;
}
}  // namespace arm

namespace tree = recursive::tree;

// A 21-link chain (axes z, y, x, ...): u' by articulated bodies above 20 speeds.
namespace chain {
constexpr std::size_t n = 21;
template <std::size_t I>
using axis_of = std::conditional_t<I % 3 == 1, kane::axis::z,
                                   std::conditional_t<I % 3 == 2, kane::axis::y, kane::axis::x>>;
template <std::size_t I>
struct B;
template <>
struct B<0> : kane::root_frame {};
template <std::size_t I>
struct B : kane::frame<B<I - 1>, kane::simple<axis_of<I>, kane::coordinate<I>>> {};
template <std::size_t I>
struct J;
template <>
struct J<1> : kane::origin<B<0>> {};
template <std::size_t I>
struct J : kane::point<J<I - 1>, literal(0.1 + 0.01 * double(I % 4)) * e<B<I - 1>, 1>> {};
template <std::size_t I>
struct C : kane::point<J<I>, literal(0.05) * e<B<I>, 1> + literal(0.01) * e<B<I>, 2>> {};
template <std::size_t I>
using link =
    kane::rigid_body<B<I>, C<I>, literal(0.5 + 0.1 * double(I % 3)),
                     kane::inertia<B<I>, C<I>, literal(0.004), literal(0.005), literal(0.006),
                                   literal(0.0003 * double(I % 2)), literal(-0.0002), literal(0.0001)>>;
template <class>
struct links;
template <std::size_t... I>
struct links<std::index_sequence<I...>> {
  using type = kane::system<link<I + 1>..., kane::torque<B<3>, -0.2 * kane::u<3> * e<B<3>, 2>>,
                            kane::gravity<literal(-9.81) * e<B<0>, 3>>>;
};
using system = links<std::make_index_sequence<n>>::type;
using state = kane::state<double, n>;
using evaluator = kane::evaluator<state, kane::frames<B<n>>, kane::level::acceleration, kane::qdot_speeds<n>>;
}  // namespace chain

using recursive::random_state;
}  // namespace

static_assert(kane::detail::recursive_form<arm::system, arm::evaluator>);
static_assert(kane::detail::recursive_form<tree::system, tree::evaluator>);
static_assert(kane::detail::recursive_form<chain::system, chain::evaluator>);

TEST_CASE("the 6R arm: inverse dynamics by inward sums is Newton-Euler by hand and M u' - f", "[recursive]") {
  std::mt19937 rng(7);
  for (int k = 0; k < 40; ++k) {
    const auto s = random_state<arm::state>(rng);
    arm::evaluator ev;
    ev.update(s);
    const auto [tau, status] = kane::inverse_dynamics<arm::system>(ev);
    REQUIRE(status == kane::solve_status::ok);
    const auto hand = arm::newton_euler(s.q.data(), s.u.data(), s.ud.data());
    CHECK((tau - hand).cwiseAbs().maxCoeff() < 1e-12);
    const auto eom = kane::mass_matrix_and_forcing<arm::system>(ev);
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> ud(s.ud.data());
    CHECK((eom.M * ud - eom.f - tau).cwiseAbs().maxCoeff() < 1e-12);
    const std::array<double, 6> rest{};
    const auto bias = arm::newton_euler(s.q.data(), s.u.data(), rest.data());
    CHECK((kane::forcing<arm::system>(ev).f + bias).cwiseAbs().maxCoeff() < 1e-12);
    // u' of forward dynamics gives tau = 0
    auto s2 = s;
    const auto [ud2, status2] = kane::forward_dynamics<arm::system>(ev);
    REQUIRE(status2 == kane::solve_status::ok);
    for (std::size_t i = 0; i < 6; ++i) s2.ud[i] = ud2(Eigen::Index(i));
    ev.update(s2);
    CHECK(kane::inverse_dynamics<arm::system>(ev).tau.cwiseAbs().maxCoeff() < 1e-11);
  }
}

TEST_CASE("joint torques as inputs per call: inverse dynamics, then the torques as inputs give back u'",
          "[recursive]") {
  std::mt19937 rng(19);
  for (int k = 0; k < 20; ++k) {
    const auto s = random_state<arm::state>(rng);
    arm::evaluator ev;
    ev.update(s);
    const auto tau = kane::inverse_dynamics<arm::system>(ev).tau;
    arm::driven_state d;
    d.q = s.q, d.u = s.u;
    arm::driven_evaluator dev;
    dev.update(d);  // r = 0: the torque-free arm
    CHECK((kane::forcing<arm::driven>(dev).f - kane::forcing<arm::system>(ev).f).cwiseAbs().maxCoeff() <
          1e-13);
    std::array<double, 6> r;
    for (std::size_t i = 0; i < 6; ++i) r[i] = tau(Eigen::Index(i));
    dev.set_inputs(r);  // no new pass
    const auto [ud, status] = kane::forward_dynamics<arm::driven>(dev);
    REQUIRE(status == kane::solve_status::ok);
    for (std::size_t i = 0; i < 6; ++i) CHECK(std::abs(ud(Eigen::Index(i)) - s.ud[i]) < 1e-10);
    kane::motion<arm::driven, arm::driven_evaluator> rhs(d);
    rhs.inputs() = r;
    std::array<double, 12> x, dx;
    for (std::size_t i = 0; i < 6; ++i) x[i] = s.q[i], x[6 + i] = s.u[i];
    rhs(x, dx, 0.0);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    for (std::size_t i = 0; i < 6; ++i) CHECK(std::abs(dx[6 + i] - s.ud[i]) < 1e-10);
  }
}

TEST_CASE("kane::motion reads x from a std::array, an Eigen vector and a strided Eigen map alike",
          "[recursive]") {
  std::mt19937 rng(23);
  const auto s = random_state<arm::state>(rng);
  kane::motion<arm::system, arm::evaluator> rhs(s);
  std::array<double, 12> x, dx;
  for (std::size_t i = 0; i < 6; ++i) x[i] = s.q[i], x[6 + i] = s.u[i];
  rhs(x, dx, 0.0);
  REQUIRE(rhs.status() == kane::solve_status::ok);
  arm::evaluator ev;
  ev.update(s);
  const auto ud = kane::forward_dynamics<arm::system>(ev).ud;
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(dx[i] == s.u[i]);
    CHECK(std::abs(dx[6 + i] - ud(Eigen::Index(i))) < 1e-12);
  }
  Eigen::Matrix<double, 12, 1> xe, dxe;
  std::array<double, 24> every_other{};  // x in the even entries, NaN between
  for (std::size_t i = 0; i < 12; ++i)
    xe(Eigen::Index(i)) = x[i], every_other[2 * i] = x[i],
    every_other[2 * i + 1] = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Map<const Eigen::Matrix<double, 12, 1>, 0, Eigen::InnerStride<2>> strided(every_other.data());
  std::array<double, 12> dxs;
  rhs(xe, dxe, 0.0);
  rhs(strided, dxs, 0.0);
  REQUIRE(rhs.status() == kane::solve_status::ok);
  for (std::size_t i = 0; i < 12; ++i) {
    CHECK(dxe(Eigen::Index(i)) == dx[i]);
    CHECK(dxs[i] == dx[i]);
  }
}

TEST_CASE(
    "a tree with fixed rotations, an oblique axis, a particle, a force and torques: M and f regrouped "
    "equal Kane's sums",
    "[recursive]") {
  std::mt19937 rng(11);
  for (int k = 0; k < 40; ++k) {
    const auto s = random_state<tree::state>(rng);
    tree::evaluator ev;
    ev.update(s);
    const auto fast = kane::mass_matrix_and_forcing<tree::system>(ev);
    const auto sums = kane::detail::equations_along<tree::system, kane::detail::rates::of_state>(
        ev, kane::detail::all_speeds<4>{});
    REQUIRE(fast.status == kane::solve_status::ok);
    CHECK((fast.M - sums.M).cwiseAbs().maxCoeff() < 1e-13);
    CHECK((fast.f - sums.f).cwiseAbs().maxCoeff() < 1e-12);
    const Eigen::Map<const Eigen::Matrix<double, 4, 1>> ud(s.ud.data());
    CHECK((kane::inverse_dynamics<tree::system>(ev).tau - (sums.M * ud - sums.f)).cwiseAbs().maxCoeff() <
          1e-12);
    CHECK((kane::mass_matrix<tree::system>(ev).M - sums.M).cwiseAbs().maxCoeff() < 1e-13);
  }
}

namespace {
// M, f and inverse dynamics by the recursive passes against Kane's sums at the state s (relative)
template <class Sys, class Ev, class State>
void against_sums(const State& s, double tolerance_m, double tolerance_f) {
  constexpr std::size_t n = Ev::nu;
  Ev ev;
  ev.update(s);
  const auto fast = kane::mass_matrix_and_forcing<Sys>(ev);
  REQUIRE(fast.status == kane::solve_status::ok);
  const auto sums =
      kane::detail::equations_along<Sys, kane::detail::rates::of_state>(ev, kane::detail::all_speeds<n>{});
  CHECK(relative(fast.M, sums.M) < tolerance_m);
  CHECK(relative(fast.f, sums.f) < tolerance_f);
  Eigen::Matrix<double, int(n), 1> ud;
  for (std::size_t i = 0; i < n; ++i) ud(Eigen::Index(i)) = s.ud[i];
  CHECK(relative(kane::inverse_dynamics<Sys>(ev).tau, sums.M * ud - sums.f) < tolerance_f);
}
}  // namespace

TEST_CASE("the tree with its joints' rates in another order as speeds: M and f regrouped equal Kane's sums",
          "[recursive]") {
  using speeds =
      kane::speeds<kane::dt(tree::q3{}), kane::dt(tree::q1{}), kane::dt(tree::q4{}), kane::dt(tree::q2{})>;
  using evaluator =
      kane::evaluator<tree::state, kane::frames<tree::T, tree::D>, kane::level::acceleration, speeds>;
  static_assert(kane::detail::recursive_form<tree::system, evaluator> &&
                !kane::detail::analytical_derivatives<tree::system, evaluator>());
  std::mt19937 rng(12);
  for (int k = 0; k < 10; ++k)
    against_sums<tree::system, evaluator>(random_state<tree::state>(rng), 1e-13, 1e-12);
}

TEST_CASE("21 links: u' by articulated bodies equals M^-1 f by composite bodies and inward sums",
          "[recursive]") {
  std::mt19937 rng(13);
  for (int k = 0; k < 10; ++k) {
    const auto s = random_state<chain::state>(rng);
    chain::evaluator ev;
    ev.update(s);
    const auto [ud, status] = kane::forward_dynamics<chain::system>(ev);
    REQUIRE(status == kane::solve_status::ok);
    const auto eom = kane::mass_matrix_and_forcing<chain::system>(ev);
    const Eigen::Matrix<double, chain::n, 1> ref = eom.M.llt().solve(eom.f);
    CHECK((ud - ref).cwiseAbs().maxCoeff() < 1e-9 * (1 + ref.cwiseAbs().maxCoeff()));
    const auto [ud2, status2] = kane::speed_derivatives(eom);  // M's Cholesky factorization by rows
    REQUIRE(status2 == kane::solve_status::ok);
    CHECK((ud2 - ref).cwiseAbs().maxCoeff() < 1e-9 * (1 + ref.cwiseAbs().maxCoeff()));
  }
}

namespace forked {  // A carries two branches, B and F-G
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::y, kane::coordinate<2>>> {};
struct F : kane::frame<A, kane::simple<kane::axis::x, kane::coordinate<3>>> {};
struct G : kane::frame<F, kane::simple<kane::axis::y, kane::coordinate<4>>> {};
struct O : kane::origin<N> {};
struct Ao : kane::point<O, 0.3 * e<A, 1>> {};
struct Bo : kane::point<Ao, 0.2 * e<B, 1> + 0.1 * e<B, 3>> {};
struct Fo : kane::point<Ao, 0.25 * e<F, 2>> {};
struct Go : kane::point<Fo, 0.2 * e<G, 3>> {};
template <class F, class P, literal M>
using body =
    kane::rigid_body<F, P, M,
                     kane::inertia<F, P, literal(0.02), literal(0.03), literal(0.025), literal(0.004)>>;
using system = kane::system<body<A, Ao, literal(1.0)>, body<B, Bo, literal(0.8)>, body<F, Fo, literal(1.2)>,
                            body<G, Go, literal(0.6)>>;
using state = kane::state<double, 4>;
using evaluator = kane::evaluator<state, kane::frames<B, G>, kane::level::pose, kane::qdot_speeds<4>>;
}  // namespace forked

// X = -M^-1 B by articulated bodies in the root's components against M from composite bodies.
template <class Sys, class Ev, class St>
void check_articulated_solve(std::mt19937& rng) {
  constexpr int n = int(Ev::nu);
  using JF = kane::detail::joint_form_of<Sys, Ev>;
  Ev ev;
  ev.update(random_state<St>(rng));
  const kane::detail::body_frames<JF, Ev> bf(ev);
  const kane::detail::tree_partials<JF, Sys, Ev> pass(bf, ev);
  const kane::detail::articulated_solve<JF, double> bodies(pass.own, pass.screw);
  REQUIRE(bodies.ok());
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::Matrix<double, n, 21> b;  // full packets of columns and one left over (any packet width)
  for (auto& v : b.reshaped()) v = d(rng);
  Eigen::Matrix<double, n, 21> x = b, y = b;
  bodies.solve_negated(x);
  const auto m = kane::mass_matrix<Sys>(ev).M;
  CHECK((m * x + b).cwiseAbs().maxCoeff() < 1e-12 * (1 + (m * x).cwiseAbs().maxCoeff()));
  // the plain-loop Cholesky of the derivatives up to 20 speeds, the same columns
  const kane::detail::cholesky_factor<double, n> factor(m);
  REQUIRE(factor.ok());
  factor.solve_negated(y);
  CHECK((m * y + b).cwiseAbs().maxCoeff() < 1e-12 * (1 + (m * y).cwiseAbs().maxCoeff()));
}

TEST_CASE("articulated bodies and Cholesky solve M X = B: two branches, a tree with a fixed tool",
          "[recursive][derivatives]") {
  std::mt19937 rng(29);
  for (int k = 0; k < 3; ++k) {
    check_articulated_solve<forked::system, forked::evaluator, forked::state>(rng);
    check_articulated_solve<tree::system, tree::evaluator, tree::state>(rng);
  }
}

TEST_CASE("the recursive entry points report a state that is not finite", "[recursive]") {
  std::mt19937 rng(17);
  auto s = random_state<arm::state>(rng);
  s.q[2] = std::numeric_limits<double>::quiet_NaN();
  arm::evaluator ev;
  ev.update(s);
  const auto [tau, status] = kane::inverse_dynamics<arm::system>(ev);
  CHECK(status == kane::solve_status::not_finite);
  CHECK(std::isnan(tau(0)));
  CHECK(kane::forcing<arm::system>(ev).status == kane::solve_status::not_finite);
  CHECK(kane::forward_dynamics<arm::system>(ev).status == kane::solve_status::not_finite);
  auto c = random_state<chain::state>(rng);
  c.u[4] = std::numeric_limits<double>::infinity();
  chain::evaluator cev;
  cev.update(c);
  const auto [ud, cstatus] = kane::forward_dynamics<chain::system>(cev);
  CHECK(cstatus == kane::solve_status::not_finite);
  CHECK(std::isnan(ud(0)));
}

TEST_CASE("dynamics derivatives: a state that is not finite gives NaN and its status", "[derivatives]") {
  std::mt19937 rng(47);
  auto s = recursive::random_state<arm::driven_state>(rng);
  s.u[2] = std::numeric_limits<double>::infinity();
  arm::driven_evaluator ev;
  ev.update(s);
  const auto id = kane::inverse_dynamics_derivatives<models::arm6::driven>(ev);
  const auto fd = kane::forward_dynamics_derivatives<models::arm6::driven>(ev);
  CHECK(id.status != kane::solve_status::ok);
  CHECK(fd.status != kane::solve_status::ok);
  CHECK(id.dtau_dq.hasNaN());
  CHECK(fd.dud_du.hasNaN());
  CHECK(fd.ud.hasNaN());
}

// A particle on D's oblique axis: u4 moves no mass.
struct on_axis : kane::point<tree::P, 0.1 * e<tree::D, 1> + 0.1 * e<tree::D, 2>> {};

TEST_CASE("dynamics derivatives: a speed that moves no mass gives singular and NaN", "[derivatives]") {
  using massless_speed = kane::system<
      kane::rigid_body<tree::A, tree::Ao, literal(1.5),
                       kane::inertia<tree::A, tree::Ao, literal(0.03), literal(0.02), literal(0.04)>>,
      kane::rigid_body<tree::B, tree::Bo, literal(1.1),
                       kane::inertia<tree::B, tree::Bo, literal(0.01), literal(0.015), literal(0.012)>>,
      kane::particle<tree::P, literal(0.7)>, kane::particle<on_axis, literal(0.5)>,
      kane::gravity<literal(-9.81) * e<tree::N, 3>>>;
  std::mt19937 rng(61);
  const auto s = recursive::random_state<tree::state>(rng);
  tree::evaluator ev;
  ev.update(s);
  const auto fd = kane::forward_dynamics_derivatives<massless_speed>(ev);
  CHECK(fd.status == kane::solve_status::singular);
  CHECK(fd.dud_dq.hasNaN());
  const auto id = kane::inverse_dynamics_derivatives<massless_speed>(ev);
  CHECK(id.status == kane::solve_status::ok);  // tau and its derivatives need no inverse
  CHECK(std::abs(id.M(3, 3)) < 1e-15);
}

namespace fa = floating_arms;

TEST_CASE("the recursive passes with a free joint carrying two two-link arms equal Kane's sums",
          "[recursive]") {
  using model = fa::model<2>;
  using system = model::system;
  using evaluator = model::evaluator;
  static_assert(kane::detail::recursive_form<system, evaluator> &&
                kane::detail::free_joint<system, evaluator>);
  for (unsigned seed : {3u, 8u})
    against_sums<system, evaluator>(fa::sample<model::state>(seed), 1e-14, 1e-13);
}

TEST_CASE("dynamics derivatives: a free joint carrying two two-link arms against central differences",
          "[derivatives]") {
  using model = fa::model<2>;
  for (unsigned seed : {3u, 8u}) {
    const auto errors = fa::derivatives_against_differences<model>(fa::sample<model::state>(seed));
    for (double x : errors) CHECK(x < 1e-7);
  }
}
