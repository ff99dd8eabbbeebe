// The analytical derivatives over kane::lanes (inverse_dynamics_derivatives,
// forward_dynamics_derivatives and kane::linearize on the recursive path), lane by lane equal to the
// scalar path, with good, singular and non-finite states in one batch.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include <catch2/catch.hpp>
#include <kane/kane.hpp>
#include <kane/scalars/lanes.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "recursive_models.hpp"

namespace {
using L = kane::lanes<double, 4>;
constexpr std::size_t W = L::width;
const double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Lane l of a matrix of lanes against the scalar path's matrix where the scalar status is ok, NaN
// where it is not: within 1e-13 (1 + the largest |entry|). Lanes round apart from the scalar path
// (their own sine and cosine), and M^-1 magnifies that in the small entries of du'/dq.
template <class ML, class M>
void same_lane(const ML& many, const M& one, std::size_t l, bool ok) {
  const double scale = 1 + (ok ? one.cwiseAbs().maxCoeff() : 0.0);
  for (Eigen::Index i = 0; i < one.rows(); ++i)
    for (Eigen::Index j = 0; j < one.cols(); ++j) {
      const double x = many(i, j)[l], y = one(i, j);
      INFO("entry (" << i << ", " << j << "): lane " << x << ", scalar " << y << ", difference " << x - y);
      if (ok)
        CHECK(std::abs(x - y) <= 1e-13 * scale);
      else
        CHECK(std::isnan(x));
    }
}

// The lanes' state of W scalar states (q, u, u', r and p alike).
template <class LS, class St>
LS gather(const std::array<St, W>& s) {
  LS ls;
  const auto fill = [&](auto& to, const auto& from) {
    if constexpr (requires { to[0]; })  // no inputs, no parameters: nothing
      for (std::size_t k = 0; k < to.size(); ++k)
        to[k] = L::generate([&](std::size_t l) { return from(l)[k]; });
  };
  fill(ls.q, [&](std::size_t l) { return s[l].q; });
  fill(ls.u, [&](std::size_t l) { return s[l].u; });
  fill(ls.ud, [&](std::size_t l) { return s[l].ud; });
  fill(ls.qd, [&](std::size_t l) { return s[l].qd; });
  fill(ls.qdd, [&](std::size_t l) { return s[l].qdd; });
  fill(ls.r, [&](std::size_t l) { return s[l].r; });
  fill(ls.p, [&](std::size_t l) { return s[l].p; });
  return ls;
}

namespace arm = models::arm6;
using arm_state = kane::state<double, 6, 6, 0, 6>;
using arm_lanes = kane::state<L, 6, 6, 0, 6>;
template <class St>
using arm_evaluator =
    kane::evaluator<St, kane::frames<arm::B6>, kane::level::acceleration, kane::qdot_speeds<6>>;
using torques = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>, kane::r<4>, kane::r<5>, kane::r<6>>;

// The tree of recursive_models.hpp with a particle of mass p_1 at Do: u_4 moves no mass where p_1 = 0.
namespace tree = recursive::tree;
using weighed_tree =
    kane::system<kane::rigid_body<tree::A, tree::Ao, kane::literal(1.5),
                                  kane::inertia<tree::A, tree::Ao, kane::literal(0.03), kane::literal(0.02),
                                                kane::literal(0.04)>>,
                 kane::rigid_body<tree::B, tree::Bo, kane::literal(1.1),
                                  kane::inertia<tree::B, tree::Bo, kane::literal(0.01), kane::literal(0.015),
                                                kane::literal(0.012)>>,
                 kane::particle<tree::P, kane::literal(0.7)>, kane::particle<tree::Do, kane::parameter<1>{}>,
                 kane::gravity<kane::literal(-9.81) * kane::e<tree::N, 3>>>;
template <class St>
using tree_evaluator =
    kane::evaluator<St, kane::frames<tree::T, tree::D>, kane::level::acceleration, kane::qdot_speeds<4>>;
}  // namespace

TEST_CASE("lanes: the 6R arm's analytical derivatives and linearization, lane by lane",
          "[lanes][derivatives]") {
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  std::array<arm_state, W> s;
  for (auto& x : s) {
    x = recursive::random_state<arm_state>(rng);
    for (auto& r : x.r) r = d(rng);
  }
  s[1].q[3] = not_a_number;                             // not finite
  s[2].u[4] = std::numeric_limits<double>::infinity();  // not finite
  const auto ls = gather<arm_lanes>(s);
  arm_evaluator<arm_lanes> lev;
  lev.update(ls);
  const auto li = kane::inverse_dynamics_derivatives<arm::driven>(lev);
  const auto lf = kane::forward_dynamics_derivatives<arm::driven>(lev);
  const auto ll = kane::linearize<arm::driven, arm_evaluator<arm_lanes>, torques>(ls);
  for (std::size_t l = 0; l < W; ++l) {
    arm_evaluator<arm_state> ev;
    ev.update(s[l]);
    const auto i = kane::inverse_dynamics_derivatives<arm::driven>(ev);
    const auto f = kane::forward_dynamics_derivatives<arm::driven>(ev);
    const auto lin = kane::linearize<arm::driven, arm_evaluator<arm_state>, torques>(s[l]);
    INFO("lane " << l);
    CHECK((l == 0 || l == 3) == (f.status == kane::solve_status::ok));
    CHECK(li.status[l] == i.status);
    CHECK(lf.status[l] == f.status);
    CHECK(ll.status[l] == lin.status);
    const bool ok = f.status == kane::solve_status::ok;
    same_lane(li.tau, i.tau, l, ok);
    same_lane(li.dtau_dq, i.dtau_dq, l, ok);
    same_lane(li.dtau_du, i.dtau_du, l, ok);
    same_lane(li.M, i.M, l, ok);
    same_lane(lf.ud, f.ud, l, ok);
    same_lane(lf.dud_dq, f.dud_dq, l, ok);
    same_lane(lf.dud_du, f.dud_du, l, ok);
    same_lane(ll.A, lin.A, l, ok);
    same_lane(ll.B, lin.B, l, ok);
  }
}

TEST_CASE("lanes: a speed that moves no mass in one lane gives singular there, the others as the scalar path",
          "[lanes][derivatives]") {
  using state = kane::state<double, 4, 4, 1>;
  using lanes_state = kane::state<L, 4, 4, 1>;
  std::mt19937 rng(73);
  std::array<state, W> s;
  for (auto& x : s) x = recursive::random_state<state>(rng), x.p[0] = 0.5;
  s[2].p[0] = 0;  // u_4 moves no mass
  s[3].u[0] = not_a_number;
  const auto ls = gather<lanes_state>(s);
  tree_evaluator<lanes_state> lev;
  lev.update(ls);
  const auto lf = kane::forward_dynamics_derivatives<weighed_tree>(lev);
  const auto li = kane::inverse_dynamics_derivatives<weighed_tree>(lev);
  const auto ll = kane::linearize<weighed_tree, tree_evaluator<lanes_state>>(ls);
  for (std::size_t l = 0; l < W; ++l) {
    tree_evaluator<state> ev;
    ev.update(s[l]);
    const auto f = kane::forward_dynamics_derivatives<weighed_tree>(ev);
    const auto i = kane::inverse_dynamics_derivatives<weighed_tree>(ev);
    const auto lin = kane::linearize<weighed_tree, tree_evaluator<state>>(s[l]);
    INFO("lane " << l);
    CHECK(f.status == (l == 2   ? kane::solve_status::singular
                       : l == 3 ? kane::solve_status::not_finite
                                : kane::solve_status::ok));
    CHECK(lf.status[l] == f.status);
    CHECK(li.status[l] == i.status);  // tau and its derivatives need no inverse: ok where p_1 = 0
    CHECK(ll.status[l] == lin.status);
    same_lane(lf.ud, f.ud, l, f.status == kane::solve_status::ok);
    same_lane(lf.dud_dq, f.dud_dq, l, f.status == kane::solve_status::ok);
    same_lane(lf.dud_du, f.dud_du, l, f.status == kane::solve_status::ok);
    same_lane(li.dtau_dq, i.dtau_dq, l, i.status == kane::solve_status::ok);
    same_lane(li.M, i.M, l, i.status == kane::solve_status::ok);
    same_lane(ll.A, lin.A, l, lin.status == kane::solve_status::ok);
  }
}
