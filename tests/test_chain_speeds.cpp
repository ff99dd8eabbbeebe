// The 24-link spatial chain with its joints' rates in reverse order as speeds against the same chain on
// qdot_speeds: many joint rates in kane::speeds, in the clang++ build (its limits on folds). Its
// articulated bodies over lanes, lane by lane as the scalar path. The 12-link chain's derivatives
// against central differences.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <utility>

#include <kane/kane.hpp>
#include <kane/scalars/lanes.hpp>

#include "../benchmarks/chain_dynamics/chain_model.hpp"
#include "derivative_checks.hpp"
#include "differences.hpp"
#include "recursive_models.hpp"

namespace {
// u_i = q_{N-i}' (i = 0..N-1)
template <class>
struct reversed;
template <std::size_t... I>
struct reversed<std::index_sequence<I...>> {
  using type = kane::speeds<kane::dt(kane::coordinate<sizeof...(I) - I>{})...>;
};
}  // namespace

TEST_CASE("the 24-link chain with its joints' rates in reverse order as speeds: u' reversed", "[recursive]") {
  constexpr std::size_t N = 24;
  using Sys = chain_model::system<N>;
  using speeds = reversed<std::make_index_sequence<N>>::type;
  using reversed_evaluator =
      kane::evaluator<chain_model::state<N>, kane::frames<chain_model::B<N>>, kane::level::pose, speeds>;
  static_assert(kane::detail::recursive_form<Sys, reversed_evaluator>);
  std::mt19937 rng(61);
  for (int k = 0; k < 3; ++k) {
    const auto s = recursive::random_state<chain_model::state<N>>(rng);
    auto r = s;
    for (std::size_t i = 0; i < N; ++i) r.u[i] = s.u[N - 1 - i];
    chain_model::evaluator<N> ev;
    reversed_evaluator rev;
    ev.update(s), rev.update(r);
    const auto a = kane::forward_dynamics<Sys>(ev), b = kane::forward_dynamics<Sys>(rev);
    REQUIRE(a.status == kane::solve_status::ok);
    REQUIRE(b.status == kane::solve_status::ok);
    CHECK(relative(Eigen::Matrix<double, int(N), 1>(b.ud.reverse()), a.ud) < 1e-12);
  }
}

TEST_CASE("lanes: the 24-link chain's articulated bodies, lane by lane as the scalar path", "[lanes]") {
  constexpr std::size_t N = 24;
  using L = kane::lanes<double, 4>;
  using Sys = chain_model::system<N>;
  using lanes_state = kane::state<L, N>;
  std::mt19937 rng(67);
  std::array<chain_model::state<N>, 4> s;
  for (auto& x : s) x = recursive::random_state<chain_model::state<N>>(rng);
  s[2].u[7] = std::numeric_limits<double>::quiet_NaN();
  lanes_state ls;
  for (std::size_t k = 0; k < N; ++k) {
    ls.q[k] = L::generate([&](std::size_t l) { return s[l].q[k]; });
    ls.u[k] = L::generate([&](std::size_t l) { return s[l].u[k]; });
  }
  kane::evaluator<lanes_state, kane::frames<chain_model::B<N>>, kane::level::pose, kane::qdot_speeds<N>> lev;
  lev.update(ls);
  const auto lf = kane::forward_dynamics<Sys>(lev);
  for (std::size_t l = 0; l < 4; ++l) {
    chain_model::evaluator<N> ev;
    ev.update(s[l]);
    const auto f = kane::forward_dynamics<Sys>(ev);
    INFO("lane " << l);
    CHECK((l == 2) == (f.status == kane::solve_status::not_finite));
    CHECK(lf.status[l] == f.status);
    for (int k = 0; k < int(N); ++k) {
      if (f.status == kane::solve_status::ok)
        CHECK(std::abs(lf.ud(k)[l] - f.ud(k)) <= 1e-13 * (1 + std::abs(f.ud(k))));
      else
        CHECK(std::isnan(lf.ud(k)[l]));
    }
  }
}

TEST_CASE("dynamics derivatives: the 12-link chain against central differences", "[derivatives]") {
  constexpr std::size_t N = 12;  // Cholesky solves
  std::mt19937 rng(53);
  const auto s = recursive::random_state<chain_model::state<N>>(rng);
  check_differences<chain_model::system<N>, chain_model::evaluator<N>>(s, 1e-12);
}
