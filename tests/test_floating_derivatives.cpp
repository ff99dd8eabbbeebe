// Analytical derivatives with a free joint (floating_arms.hpp): the floating base with two eight-link
// arms (22 speeds) and the base alone (its u' by Kane's sums, M known), against central differences of
// kane's inverse and forward dynamics along the motion of each speed (1e-7 relative), and
// kane::linearize by them against jets through the whole evaluator (1e-10), the Euler parameters'
// columns along the turns of the base.
#include <catch2/catch.hpp>

#include <cstddef>

#include <kane/kane.hpp>

#include "differences.hpp"
#include "floating_arms.hpp"

namespace fa = floating_arms;

TEST_CASE("dynamics derivatives: a floating base with two eight-link arms against differences and jets",
          "[derivatives]") {
  using model = fa::model<8>;
  constexpr std::size_t nq = model::state::nq, nu = model::state::nu;
  auto s = fa::sample<model::state>(5);
  for (std::size_t i = 0; i < 4; ++i) s.q[i] *= 1.2;  // |e| = 1.2: q' and its rows hold at any norm
  const auto errors = fa::derivatives_against_differences<model>(s, 1e-5);
  for (double x : errors) CHECK(x < 1e-7);
  // kane::linearize by the derivatives against jets in batches through the whole evaluator
  const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
  const auto jets = kane::detail::linearize_in_batches<model::system, model::evaluator, model::inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  REQUIRE(jets.status == kane::solve_status::ok);
  const auto t = fa::tangent(s);
  CHECK(relative(lin.A * t, jets.A * t) < 1e-10);
  CHECK(relative(lin.A.topRows<int(nq)>(), jets.A.topRows<int(nq)>()) < 1e-10);
  CHECK(relative(lin.B, jets.B) < 1e-10);
  CHECK(relative(lin.rate, jets.rate) < 1e-12);
  model::evaluator ev;
  ev.update(s);
  const auto d = kane::forward_dynamics_derivatives<model::system>(ev);
  REQUIRE(d.status == kane::solve_status::ok);
  const Eigen::Matrix<double, int(nu), int(2 * nu)> tangent_rows = jets.A.bottomRows<int(nu)>() * t;
  CHECK(relative(d.dud_dq, tangent_rows.leftCols<int(nu)>()) < 1e-10);
  CHECK(relative(d.dud_du, tangent_rows.rightCols<int(nu)>()) < 1e-10);
}

namespace lone {  // the base alone, a thrust and torques: its dynamics by Kane's sums, M known
using namespace floating_arms;
constexpr auto w = kane::angular_velocity<N, B>();
struct model {
  using system =
      kane::system<base, kane::gravity<literal(-9.81) * e<N, 3>>, kane::force<Bo, kane::r<1> * e<B, 3>>,
                   kane::torque<B, kane::r<2> * e<B, 1> + kane::r<3> * e<B, 2>>>;
  using speeds = kane::speeds<dot(w, e<B, 1>), dot(w, e<B, 2>), dot(w, e<B, 3>), dt(q<5>{}), dt(q<6>{}),
                              dt(q<7>{}), kane::unit_norm<B>>;
  using state = kane::state_of<system, speeds>;
  using evaluator = kane::system_evaluator<system, speeds>;
  using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>>;
};
}  // namespace lone

TEST_CASE(
    "dynamics derivatives: a free body alone, its dynamics by Kane's sums, against differences and jets",
    "[derivatives]") {
  using model = lone::model;
  static_assert(!kane::detail::recursive_form<model::system, model::evaluator> &&
                kane::detail::free_joint<model::system, model::evaluator>);
  const auto s = fa::sample<model::state>(13);
  for (double x : fa::derivatives_against_differences<model>(s)) CHECK(x < 1e-7);
  const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
  const auto jets = kane::detail::linearize_in_batches<model::system, model::evaluator, model::inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  const auto t = fa::tangent(s);
  CHECK(relative((lin.A * t).eval(), (jets.A * t).eval()) < 1e-10);
  CHECK(relative(lin.A.topRows<7>(), jets.A.topRows<7>()) < 1e-10);
  CHECK(relative(lin.B, jets.B) < 1e-10);
}
