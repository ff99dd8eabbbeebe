// Analytical derivatives of the 12- and 48-link spatial chains' inverse and forward dynamics against
// central differences of kane's own (1e-7 relative, scaled by the chain's condition), and kane::linearize
// of the 48-link chain through them.
#include <catch2/catch.hpp>

#include <cstddef>
#include <random>

#include <kane/kane.hpp>

#include "../benchmarks/chain_dynamics/chain_model.hpp"
#include "differences.hpp"
#include "recursive_models.hpp"

namespace {
constexpr std::size_t n = 48;
using model = chain_model::system<n>;
using state = chain_model::state<n>;
using evaluator = chain_model::evaluator<n>;

// Every derivative of the N-link chain against central differences, M against composite bodies.
template <std::size_t N>
void check_chain(std::mt19937& rng) {
  using Sys = chain_model::system<N>;
  using Ev = chain_model::evaluator<N>;
  const auto s = recursive::random_state<chain_model::state<N>>(rng);
  Ev ev;
  ev.update(s);
  const auto id = kane::inverse_dynamics_derivatives<Sys>(ev);
  const auto fd = kane::forward_dynamics_derivatives<Sys>(ev);
  REQUIRE(id.status == kane::solve_status::ok);
  REQUIRE(fd.status == kane::solve_status::ok);
  const auto tau = [](const Ev& x) { return kane::inverse_dynamics<Sys>(x).tau; };
  const auto ud = [](const Ev& x) { return kane::forward_dynamics<Sys>(x).ud; };
  Eigen::Matrix<double, int(N), int(N)> tq, tu, aq, au;
  for (std::size_t j = 0; j < N; ++j) {
    const auto c = Eigen::Index(j);
    tq.col(c) = central<Ev, false>(s, j, tau), tu.col(c) = central<Ev, true>(s, j, tau);
    aq.col(c) = central<Ev, false>(s, j, ud), au.col(c) = central<Ev, true>(s, j, ud);
  }
  CHECK(relative(id.dtau_dq, tq) < 1e-7);
  CHECK(relative(id.dtau_du, tu) < 1e-7);
  CHECK(relative(fd.dud_dq, aq) < 1e-7);
  CHECK(relative(fd.dud_du, au) < 1e-7);
  CHECK(relative(id.M, kane::mass_matrix<Sys>(ev).M) < 1e-12);
  CHECK(relative(fd.ud, kane::forward_dynamics<Sys>(ev).ud) < 1e-10);
}

}  // namespace

TEST_CASE("dynamics derivatives: the 12- and 48-link chains against central differences", "[derivatives]") {
  std::mt19937 rng(53);
  check_chain<48>(rng);  // articulated bodies solve
  check_chain<12>(rng);  // Cholesky solves
}

TEST_CASE("linearize: the 48-link chain through the analytical derivatives", "[derivatives]") {
  std::mt19937 rng(59);
  const auto s = recursive::random_state<state>(rng);
  const auto lin = kane::linearize<model, evaluator>(s);
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
