// The Whipple bicycle's first-order linearization (examples/models/bicycle.hpp with the bodies of
// Meijaard et al. 2007): the 8 x 8 A of linearize_constrained in (q_ind, u_ind) holds the lean
// and steer eigenvalues of the benchmark's M, C, K form (bicycle_linear.hpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "../examples/models/bicycle.hpp"
#include "../examples/models/bicycle_linear.hpp"
#include "eigenvalues.hpp"

namespace b = models::bicycle;

TEST_CASE("bicycle: the first-order A of (q_ind, u_ind) holds the lean and steer eigenvalues") {
  b::dynamics_state s = b::benchmark_parameters();
  s.q = {0.3, -0.2, 0.7, 0, 0, 0};  // where and whither it rolls does not matter
  s.u[6] = 5 / s.p[1];
  const auto lin = kane::linearize_constrained<b::system, b::rolling, b::dynamics_evaluator, b::pitch>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  const Eigen::VectorXcd all = eigenvalues_of(lin.A);
  for (const auto& want : b::upright_eigenvalues(5)) {
    double nearest = INFINITY;
    for (Eigen::Index i = 0; i < all.size(); ++i) nearest = std::min(nearest, std::abs(all(i) - want));
    CHECK(nearest < 1e-11 * std::abs(want));
  }
}
