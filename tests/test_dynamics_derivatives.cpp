// Analytical derivatives of inverse and forward dynamics (kane::inverse_dynamics_derivatives,
// kane::forward_dynamics_derivatives) against central differences of kane's own inverse and
// forward dynamics: a branched tree with an oblique axis, a fixed tool, a particle and loads fixed
// in their bodies; the 6R arm driven by joint torques, also against jets carried through forward
// dynamics. (Their statuses: tests/test_recursive_dynamics.cpp, which the sanitizers run.)
#include <catch2/catch.hpp>

#include <cstddef>
#include <random>

#include <kane/kane.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "derivative_checks.hpp"
#include "differences.hpp"
#include "recursive_models.hpp"

namespace {
namespace tree = recursive::tree;
using kane::e;
using kane::literal;

// The tree's bodies with loads whose components are constant in the bodies they act on.
using steady_tree = kane::system<
    kane::rigid_body<tree::A, tree::Ao, literal(1.5),
                     kane::inertia<tree::A, tree::Ao, literal(0.03), literal(0.02), literal(0.04)>>,
    kane::rigid_body<
        tree::B, tree::Bo, literal(1.1),
        kane::inertia<tree::B, tree::Bo, literal(0.01), literal(0.015), literal(0.012), literal(0.001)>>,
    kane::rigid_body<tree::T, tree::To, literal(0.4),
                     kane::inertia<tree::T, tree::To, literal(0.004), literal(0.003), literal(0.005),
                                   literal(0.0), literal(0.0005), literal(-0.0002)>>,
    kane::particle<tree::P, literal(0.7)>,
    kane::rigid_body<
        tree::D, tree::Do, literal(0.9),
        kane::inertia<tree::D, tree::Do, literal(0.02), literal(0.01), literal(0.025), literal(0.002)>>,
    kane::force<tree::To, 2.0 * e<tree::B, 3> + 0.5 * e<tree::T, 1>>,
    kane::torque<tree::C, 0.3 * e<tree::C, 1>>, kane::torque<tree::D, 0.5 * e<tree::D, 3>>,
    kane::gravity<literal(-9.81) * e<tree::N, 3>>>;

using arm_state = kane::state<double, 6, 6, 0, 6>;
using arm_evaluator = kane::evaluator<arm_state, kane::frames<models::arm6::B6>, kane::level::acceleration,
                                      kane::qdot_speeds<6>>;

// du'/dq and du'/du against jets of two random directions (dq, du) through forward_dynamics (1e-10
// relative to the derivatives' size).
template <class Sys, class Ev, class St>
void check_jets(const St& s, std::mt19937& rng) {
  constexpr std::size_t n = Ev::nu;
  using J = kane::jet<double, 2>;
  using JEv = typename kane::detail::rebind_evaluator<Ev, J>::type;
  using directions = Eigen::Matrix<double, int(n), 2>;
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  directions dq, du;
  for (Eigen::Index i = 0; i < Eigen::Index(n); ++i)
    for (Eigen::Index k = 0; k < 2; ++k) dq(i, k) = d(rng), du(i, k) = d(rng);
  const auto along = [&](double x, const directions& m, std::size_t i) {
    const auto r = Eigen::Index(i);
    return J(x) + J::variable(0.0, 0) * m(r, 0) + J::variable(0.0, 1) * m(r, 1);
  };
  auto js = kane::detail::lift<2>(s);
  for (std::size_t i = 0; i < n; ++i)
    js.q[i] = along(s.q[i], dq, i), js.qd[i] = along(s.qd[i], du, i), js.u[i] = along(s.u[i], du, i);
  JEv jev;
  jev.update(js);
  const auto jud = kane::forward_dynamics<Sys>(jev).ud;
  Ev ev;
  ev.update(s);
  const auto fd = kane::forward_dynamics_derivatives<Sys>(ev);
  directions exact = fd.dud_dq * dq + fd.dud_du * du, jets;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = 0; k < 2; ++k) jets(Eigen::Index(r), Eigen::Index(k)) = jud(Eigen::Index(r)).part(k);
  const double scale = fd.dud_dq.cwiseAbs().maxCoeff() + fd.dud_du.cwiseAbs().maxCoeff();
  CHECK((exact - jets).cwiseAbs().maxCoeff() < 1e-10 * (1 + scale));
}
}  // namespace

TEST_CASE("dynamics derivatives: a branched tree against central differences", "[derivatives]") {
  std::mt19937 rng(41);
  for (int k = 0; k < 5; ++k) {
    const auto s = recursive::random_state<tree::state>(rng);
    check_differences<steady_tree, tree::evaluator>(s);
  }
}

TEST_CASE("dynamics derivatives: the 6R arm driven by joint torques", "[derivatives]") {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> torque(-5, 5);
  for (int k = 0; k < 5; ++k) {
    auto s = recursive::random_state<arm_state>(rng);
    for (auto& r : s.r) r = torque(rng);
    check_differences<models::arm6::driven, arm_evaluator>(s);
    check_jets<models::arm6::driven, arm_evaluator>(s, rng);
  }
}

TEST_CASE("linearize: the driven 6R arm's A and B against central differences of forward dynamics",
          "[derivatives]") {
  using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>, kane::r<4>, kane::r<5>, kane::r<6>>;
  using Sys = models::arm6::driven;
  std::mt19937 rng(59);
  std::uniform_real_distribution<double> torque(-5, 5);
  auto s = recursive::random_state<arm_state>(rng);
  for (auto& r : s.r) r = torque(rng);
  const auto lin = kane::linearize<Sys, arm_evaluator, inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  const auto ud = [](const arm_state& x) {
    arm_evaluator ev;
    ev.update(x);
    return kane::forward_dynamics<Sys>(ev).ud;
  };
  Eigen::Matrix<double, 12, 12> a = Eigen::Matrix<double, 12, 12>::Zero();
  Eigen::Matrix<double, 12, 6> b = Eigen::Matrix<double, 12, 6>::Zero();
  a.topRightCorner<6, 6>().setIdentity();
  const double h = 1e-6;
  for (std::size_t j = 0; j < 6; ++j) {
    arm_state p = s, m = s;
    p.q[j] += h, m.q[j] -= h;
    a.block<6, 1>(6, Eigen::Index(j)) = (ud(p) - ud(m)) / (2 * h);
    p = s, m = s, p.u[j] += h, m.u[j] -= h;
    a.block<6, 1>(6, Eigen::Index(6 + j)) = (ud(p) - ud(m)) / (2 * h);
    p = s, m = s, p.r[j] += h, m.r[j] -= h;
    b.block<6, 1>(6, Eigen::Index(j)) = (ud(p) - ud(m)) / (2 * h);
  }
  CHECK(relative(lin.A, a) < 1e-7);
  CHECK(relative(lin.B, b) < 1e-7);
  CHECK(relative(lin.rate.tail<6>(), ud(s)) < 1e-12);
}

// The driven arm with loads nonlinear in the inputs, one a force at a point: B from the loads' partial
// derivatives by the inputs against central differences and against jets through the whole evaluator.
namespace pushed {
using namespace models::arm6;
using system = kane::system<driven, kane::force<C4, kane::sin(kane::r<1>) * e<B4, 2>>,
                            kane::torque<B5, kane::r<2> * kane::r<3> * e<B5, 1>>>;
// a parameter among the inputs: B by jets through inverse dynamics
using weighed =
    kane::system<driven, kane::force<C4, kane::parameter<1>{} * kane::sin(kane::r<1>) * e<B4, 2>>>;
using state = kane::state<double, 6, 6, 1, 6>;
using evaluator = kane::evaluator<state, kane::frames<B6>, kane::level::acceleration, kane::qdot_speeds<6>>;
}  // namespace pushed

TEST_CASE("linearize: loads nonlinear in the inputs, B against central differences and jets",
          "[derivatives]") {
  using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>>;
  using Sys = pushed::system;
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> torque(-5, 5);
  auto s = recursive::random_state<arm_state>(rng);
  for (auto& r : s.r) r = torque(rng);
  const auto lin = kane::linearize<Sys, arm_evaluator, inputs>(s);
  const auto jets = kane::detail::linearize_in_batches<Sys, arm_evaluator, inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  REQUIRE(jets.status == kane::solve_status::ok);
  CHECK(relative(lin.B, jets.B) < 1e-10);
  CHECK(relative(lin.A, jets.A) < 1e-10);
  const auto ud = [](const arm_state& x) {
    arm_evaluator ev;
    ev.update(x);
    return kane::forward_dynamics<Sys>(ev).ud;
  };
  Eigen::Matrix<double, 12, 3> b = Eigen::Matrix<double, 12, 3>::Zero();
  const double h = 1e-6;
  for (std::size_t j = 0; j < 3; ++j) {
    arm_state p = s, m = s;
    p.r[j] += h, m.r[j] -= h;
    b.block<6, 1>(6, Eigen::Index(j)) = (ud(p) - ud(m)) / (2 * h);
  }
  CHECK(relative(lin.B, b) < 1e-7);
  CHECK(lin.B.col(0).norm() > 0);
  CHECK(lin.B.col(2).norm() > 0);
}

TEST_CASE("linearize: a parameter among the inputs, B against central differences", "[derivatives]") {
  using inputs = kane::inputs<kane::parameter<1>{}, kane::r<1>>;
  using Sys = pushed::weighed;
  using St = pushed::state;
  std::mt19937 rng(67);
  std::uniform_real_distribution<double> torque(-5, 5);
  auto s = recursive::random_state<St>(rng);
  for (auto& r : s.r) r = torque(rng);
  s.p = {2.5};
  const auto lin = kane::linearize<Sys, pushed::evaluator, inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  const auto ud = [](const St& x) {
    pushed::evaluator ev;
    ev.update(x);
    return kane::forward_dynamics<Sys>(ev).ud;
  };
  Eigen::Matrix<double, 12, 2> b = Eigen::Matrix<double, 12, 2>::Zero();
  const double h = 1e-6;
  St p = s, m = s;
  p.p[0] += h, m.p[0] -= h;
  b.block<6, 1>(6, 0) = (ud(p) - ud(m)) / (2 * h);
  p = s, m = s, p.r[0] += h, m.r[0] -= h;
  b.block<6, 1>(6, 1) = (ud(p) - ud(m)) / (2 * h);
  CHECK(relative(lin.B, b) < 1e-7);
  CHECK(lin.B.col(0).norm() > 0);
}
