// Every analytical derivative of the N-link spatial chain (benchmarks/chain_dynamics) against central
// differences of kane's own inverse and forward dynamics (1e-7 relative), M against composite bodies.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <random>

#include <kane/kane.hpp>

#include "../benchmarks/chain_dynamics/chain_model.hpp"
#include "differences.hpp"
#include "recursive_models.hpp"

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
