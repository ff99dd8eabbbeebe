// The analytical derivatives of a system's inverse and forward dynamics against central differences of
// kane's own (1e-7 relative); tau, M and u' against inverse_dynamics, mass_matrix and forward_dynamics
// (exact relative, u' 100 exact).
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>

#include <kane/kane.hpp>

#include "differences.hpp"

template <class Sys, class Ev, class St>
void check_differences(const St& s, double exact = 1e-14) {
  constexpr std::size_t n = Ev::nu;
  Ev ev;
  ev.update(s);
  const auto id = kane::inverse_dynamics_derivatives<Sys>(ev);
  const auto fd = kane::forward_dynamics_derivatives<Sys>(ev);
  REQUIRE(id.status == kane::solve_status::ok);
  REQUIRE(fd.status == kane::solve_status::ok);
  CHECK(relative(id.tau, kane::inverse_dynamics<Sys>(ev).tau) < exact);
  CHECK(relative(id.M, kane::mass_matrix<Sys>(ev).M) < exact);
  CHECK(relative(fd.ud, kane::forward_dynamics<Sys>(ev).ud) < 100 * exact);
  const auto tau = [](const Ev& x) { return kane::inverse_dynamics<Sys>(x).tau; };
  const auto ud = [](const Ev& x) { return kane::forward_dynamics<Sys>(x).ud; };
  Eigen::Matrix<double, int(n), int(n)> tq, tu, aq, au;
  for (std::size_t j = 0; j < n; ++j) {
    const auto c = Eigen::Index(j);
    tq.col(c) = central<Ev, false>(s, j, tau), tu.col(c) = central<Ev, true>(s, j, tau);
    aq.col(c) = central<Ev, false>(s, j, ud), au.col(c) = central<Ev, true>(s, j, ud);
  }
  CHECK(relative(id.dtau_dq, tq) < 1e-7);
  CHECK(relative(id.dtau_du, tu) < 1e-7);
  CHECK(relative(fd.dud_dq, aq) < 1e-7);
  CHECK(relative(fd.dud_du, au) < 1e-7);
}
