// Analytical derivatives of the 48-link spatial chain's inverse and forward dynamics against central
// differences of kane's own (1e-7 relative), and kane::linearize of the chain through them.
#include <catch2/catch.hpp>

#include <cstddef>
#include <random>

#include <kane/kane.hpp>

#include "../benchmarks/chain_dynamics/chain_model.hpp"
#include "allocations.hpp"
#include "derivative_checks.hpp"
#include "differences.hpp"
#include "recursive_models.hpp"

namespace {
constexpr std::size_t n = 48;
using model = chain_model::system<n>;
using state = chain_model::state<n>;
using evaluator = chain_model::evaluator<n>;
}  // namespace

TEST_CASE("dynamics derivatives: the 48-link chain against central differences", "[derivatives]") {
  std::mt19937 rng(53);
  check_differences<model, evaluator>(recursive::random_state<state>(rng), 1e-12);  // articulated bodies
}

TEST_CASE("linearize: the 48-link chain through the analytical derivatives", "[derivatives]") {
  std::mt19937 rng(59);
  const auto s = recursive::random_state<state>(rng);
  const long before = allocations::count();
  const auto lin = kane::linearize<model, evaluator>(s);
  const long allocated = allocations::count() - before;
  CHECK(allocated == 0);
  REQUIRE(lin.status == kane::solve_status::ok);
  evaluator ev;
  ev.update(s);
  const auto fd = kane::forward_dynamics_derivatives<model>(ev);
  constexpr auto m = Eigen::Index(n);
  CHECK(lin.A.topLeftCorner<m, m>().isZero(0));
  CHECK(lin.A.topRightCorner<m, m>().isIdentity(0));
  CHECK(relative(lin.A.bottomLeftCorner<m, m>(), fd.dud_dq) == 0);
  CHECK(relative(lin.A.bottomRightCorner<m, m>(), fd.dud_du) == 0);
  CHECK(relative(lin.rate.tail<m>(), kane::forward_dynamics<model>(ev).ud) < 1e-10);
}
