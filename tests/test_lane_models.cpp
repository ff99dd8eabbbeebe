// kane::lanes through constrained_motion (the rolling disc, the Whipple bicycle), the recursive
// path's forward and inverse dynamics, M and f (the 6R arm), the energies and momenta (the heavy top)
// and Newton's method on a holonomic loop (the four-bar), lane by lane equal to the scalar path, with
// good, singular and non-finite states mixed in one batch.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../examples/models/arm6_dynamics.hpp"
#include "../examples/models/bicycle.hpp"
#include "../examples/models/disc.hpp"
#include "../examples/models/fourbar.hpp"
#include "../examples/models/heavy_top.hpp"
#include "lanes_compare.hpp"

namespace {
using lanes_test::compare;
using lanes_test::states;
}  // namespace

TEST_CASE("lanes: the rolling disc's constrained motion, lane by lane as the scalar path", "[lanes]") {
  namespace d = models::disc;
  using L = kane::lanes<double, 8>;
  kane::state_of<d::system, d::rolling::speed_set> s;
  s.p = {0.3, 2.0, 9.81};  // r, m, g
  kane::state_of<d::system, d::rolling::speed_set, L> ls;
  ls.p = {L(0.3), L(2.0), L(9.81)};
  kane::constrained_motion<d::system, d::rolling> one(s);
  kane::constrained_motion<d::system, d::rolling, L> many(ls);
  auto xs = states<double, 8>(11, 13);
  xs[3][4] = std::numeric_limits<double>::quiet_NaN();
  xs[9][1] = std::numeric_limits<double>::infinity();
  compare(one, many, xs, 1e-13);
  lanes_test::compare_soa(one, many, xs, 1e-13);  // from and to structure-of-arrays buffers
}

TEST_CASE("lanes: the 6R arm's forward and inverse dynamics on the recursive path, lane by lane", "[lanes]") {
  namespace a = models::arm6;
  using L = kane::lanes<double, 8>;
  using state = kane::state<double, 6>;
  using lstate = kane::state<L, 6>;
  using frames = kane::frames<a::B6>;
  using evaluator = kane::evaluator<state, frames, kane::level::pose, kane::qdot_speeds<6>>;
  using levaluator = kane::evaluator<lstate, frames, kane::level::pose, kane::qdot_speeds<6>>;
  const auto xs = states<double, 18>(8, 17);  // q, u, u'
  lstate ls;
  for (std::size_t k = 0; k < 6; ++k) {
    ls.q[k] = L::generate([&](std::size_t l) { return xs[l][k]; });
    ls.u[k] = L::generate([&](std::size_t l) { return xs[l][6 + k]; });
    ls.ud[k] = L::generate([&](std::size_t l) { return xs[l][12 + k]; });
  }
  ls.q[2].set(5, std::numeric_limits<double>::quiet_NaN());
  levaluator lev;
  lev.update(ls);
  const auto lf = kane::forward_dynamics<a::links>(lev);
  const auto li = kane::inverse_dynamics<a::links>(lev);
  const auto le = kane::mass_matrix_and_forcing<a::links>(lev);
  for (std::size_t l = 0; l < 8; ++l) {
    state s;
    for (std::size_t k = 0; k < 6; ++k) s.q[k] = ls.q[k][l], s.u[k] = ls.u[k][l], s.ud[k] = ls.ud[k][l];
    evaluator ev;
    ev.update(s);
    const auto f = kane::forward_dynamics<a::links>(ev);
    const auto i = kane::inverse_dynamics<a::links>(ev);
    const auto e = kane::mass_matrix_and_forcing<a::links>(ev);
    INFO("lane " << l);
    CHECK(lf.status[l] == f.status);
    CHECK(li.status[l] == i.status);
    CHECK(le.status[l] == e.status);
    CHECK((l == 5) == (f.status == kane::solve_status::not_finite));
    for (int k = 0; k < 6; ++k) {
      if (f.status == kane::solve_status::ok) {
        CHECK(std::abs(lf.ud(k)[l] - f.ud(k)) <= 1e-13 * (1 + std::abs(f.ud(k))));
        CHECK(std::abs(li.tau(k)[l] - i.tau(k)) <= 1e-13 * (1 + std::abs(i.tau(k))));
        CHECK(std::abs(le.f(k)[l] - e.f(k)) <= 1e-13 * (1 + std::abs(e.f(k))));
        for (int j = 0; j < 6; ++j)
          CHECK(std::abs(le.M(k, j)[l] - e.M(k, j)) <= 1e-13 * (1 + std::abs(e.M(k, j))));
      } else {
        CHECK(std::isnan(lf.ud(k)[l]));
        CHECK(std::isnan(li.tau(k)[l]));
      }
    }
  }
}

TEST_CASE("lanes: the Whipple bicycle's constrained motion, lane by lane as the scalar path", "[lanes]") {
  namespace b = models::bicycle;
  using L = kane::lanes<double, 8>;
  using lstate = kane::state<L, 6, 8, 27>;
  using levaluator =
      kane::evaluator<lstate, kane::frames<b::Wr, b::Wf>, kane::level::acceleration, b::speeds>;
  const b::dynamics_state s = b::benchmark_parameters();
  lstate ls;
  for (std::size_t i = 0; i < 27; ++i) ls.p[i] = L(s.p[i]);
  kane::constrained_motion<b::system, b::rolling, b::dynamics_evaluator> one(s);
  kane::constrained_motion<b::system, b::rolling, levaluator> many(ls);
  auto xs = states<double, 9>(10, 19);
  for (auto& x : xs) x[4] = 0.1 * x[4];  // pitch near its value on flat ground
  xs[2][8] = std::numeric_limits<double>::quiet_NaN();
  compare(one, many, xs, 1e-12);
}

TEST_CASE("lanes: the heavy top's energies and momenta, lane by lane as the scalar path", "[lanes]") {
  namespace t = models::heavy_top;
  using L = kane::lanes<double, 4>;
  const auto xs = states<double, 6>(4, 23);  // q, u
  kane::state<L, 3> ls;
  for (std::size_t k = 0; k < 3; ++k) {
    ls.q[k] = L::generate([&](std::size_t l) { return xs[l][k]; });
    ls.u[k] = L::generate([&](std::size_t l) { return xs[l][3 + k]; });
  }
  ls.u[1].set(2, std::numeric_limits<double>::quiet_NaN());  // lane 2: NaN in, NaN out
  kane::evaluator<kane::state<L, 3>, kane::frames<t::C>, kane::level::velocity, t::speeds> lev;
  lev.update(ls);
  const L T = kane::kinetic_energy<t::system>(lev), V = kane::potential_energy<t::system>(lev);
  const auto p = kane::linear_momentum<t::system>(lev);
  const auto h = kane::angular_momentum<t::system, t::O>(lev);
  for (std::size_t l = 0; l < 4; ++l) {
    kane::state<double, 3> s;
    for (std::size_t k = 0; k < 3; ++k) s.q[k] = ls.q[k][l], s.u[k] = ls.u[k][l];
    kane::evaluator<kane::state<double, 3>, kane::frames<t::C>, kane::level::velocity, t::speeds> ev;
    ev.update(s);
    INFO("lane " << l);
    CHECK(lev.status()[l] == ev.status());
    const double T1 = kane::kinetic_energy<t::system>(ev), V1 = kane::potential_energy<t::system>(ev);
    const auto p1 = kane::linear_momentum<t::system>(ev);
    const auto h1 = kane::angular_momentum<t::system, t::O>(ev);
    const auto same = [](double a, double b) {
      return std::isnan(b) ? std::isnan(a) : std::abs(a - b) <= 1e-13 * (1 + std::abs(b));
    };
    CHECK(same(T[l], T1));
    CHECK(same(V[l], V1));
    for (int i = 0; i < 3; ++i) {
      CHECK(same(p[i][l], p1[i]));
      CHECK(same(h[i][l], h1[i]));
    }
    if (l == 2) CHECK(std::isnan(T1));
  }
}

TEST_CASE("lanes: Newton's method on the four-bar loop, each lane stopping on its own as the scalar path",
          "[lanes]") {
  namespace f = models::fourbar;
  using L = kane::lanes<double, 4>;
  using lstate = kane::state<L, 3, 3, 4>;
  using levaluator =
      kane::evaluator<lstate, kane::frames<f::A, f::B, f::C>, kane::level::velocity, f::speeds>;
  // lanes: two starts that close in different steps, a singular Jacobian (q2 = q3), NaN; then a
  // loop that cannot close (ground 5) beside one that closes
  const std::array<std::array<double, 4>, 8> starts{{{0.7, 0.3, 1.6, 1.1},
                                                     {-2.5, 0.3, 1.6, 1.1},
                                                     {0.7, 1.0, 1.0, 1.1},
                                                     {std::nan(""), 0.3, 1.6, 1.1},
                                                     {0.7, 0.3, 1.6, 5.0},
                                                     {1.5, 0.3, 1.6, 1.1},
                                                     {0.7, 0.3, 1.6, 5.0},
                                                     {3.0, 0.3, 1.6, 1.1}}};
  const kane::solve_status expected[8] = {kane::solve_status::ok,
                                          kane::solve_status::ok,
                                          kane::solve_status::singular,
                                          kane::solve_status::not_finite,
                                          kane::solve_status::not_converged,
                                          kane::solve_status::ok,
                                          kane::solve_status::not_converged,
                                          kane::solve_status::ok};
  for (std::size_t first = 0; first < 8; first += 4) {
    lstate ls;
    ls.p = {L(0.3), L(1.0), L(0.8), L::generate([&](std::size_t l) { return starts[first + l][3]; })};
    for (std::size_t k = 0; k < 3; ++k)
      ls.q[k] = L::generate([&](std::size_t l) { return starts[first + l][k]; });
    levaluator lev;
    const auto r = kane::solve_configuration<f::loop>(lev, ls, {1e-12, 30});
    std::size_t most = 0;
    for (std::size_t l = 0; l < 4; ++l) {
      f::state s;
      s.p = {0.3, 1.0, 0.8, starts[first + l][3]};
      s.q = {starts[first + l][0], starts[first + l][1], starts[first + l][2]};
      f::evaluator ev;
      const auto r1 = kane::solve_configuration<f::loop>(ev, s, {1e-12, 30});
      INFO("start " << first + l);
      CHECK(r1.status == expected[first + l]);
      CHECK(r.status[l] == r1.status);
      most = r1.iterations > most ? r1.iterations : most;
      if (r1.status == kane::solve_status::not_converged) {  // chaotic iterates: the gap stays
        CHECK(r.residual[l] > 1.0);
        continue;
      }
      CHECK((std::isnan(r1.residual) ? std::isnan(r.residual[l])
                                     : std::abs(r.residual[l] - r1.residual) <= 1e-12));
      for (std::size_t k = 0; k < 3; ++k)
        CHECK((std::isnan(s.q[k]) ? std::isnan(ls.q[k][l])
                                  : std::abs(ls.q[k][l] - s.q[k]) <= 1e-13 * (1 + std::abs(s.q[k]))));
    }
    CHECK(r.iterations == most);
  }
}
