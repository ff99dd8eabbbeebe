// Threads: one batch of states evaluated in one thread, then split across four, each thread with
// its own right-hand side or evaluator. kane keeps no state of its own outside the objects a user
// makes, so the results are the same bits, statuses and NaN included.
#include <catch2/catch.hpp>

#include <array>
#include <cstring>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include <kane/kane.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "../examples/models/disc.hpp"

namespace {
namespace d = models::disc;
using disc_rhs = kane::constrained_motion<d::system, d::rolling>;
using disc_state = kane::state_of<d::system, d::speeds5>;
using arm_state = kane::state<double, 6, 6, 0, 6>;
using arm_evaluator = kane::evaluator<arm_state, kane::frames<models::arm6::B6>, kane::level::acceleration,
                                      kane::qdot_speeds<6>>;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// work(w, i) for i in [0, n), in t threads, each on its share with its own w = make()
template <class Make, class Work>
void split(std::size_t n, std::size_t t, const Make& make, const Work& work) {
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < t; ++k)
    threads.emplace_back([&, k] {
      auto w = make();
      for (std::size_t i = n * k / t; i < n * (k + 1) / t; ++i) work(w, i);
    });
  for (auto& x : threads) x.join();
}
// status = work(w, i, out + i m) for n items in one thread and in four: the same bits and statuses;
// the statuses of one thread
template <class Make, class Work>
std::vector<int> one_and_four(std::size_t n, std::size_t m, const Make& make, const Work& work) {
  std::vector<double> one(n * m), four(n * m);
  std::vector<int> status_one(n), status_four(n);
  split(n, 1, make, [&](auto& w, std::size_t i) { status_one[i] = work(w, i, &one[i * m]); });
  split(n, 4, make, [&](auto& w, std::size_t i) { status_four[i] = work(w, i, &four[i * m]); });
  CHECK(std::memcmp(one.data(), four.data(), one.size() * sizeof(double)) == 0);
  CHECK(status_one == status_four);
  return status_one;
}
}  // namespace

TEST_CASE("threads: a batch split across four threads gives the bits of one thread", "[threads]") {
  constexpr std::size_t n = 200;
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> unit(-1, 1);

  // the rolling disc by kane::constrained_motion: Kane's sums and the rolling constraints
  constexpr std::size_t m = disc_rhs::size;
  std::vector<std::array<double, m>> xs(n);
  for (auto& x : xs)
    for (auto& v : x) v = unit(rng);
  xs[11][6] = not_a_number;
  disc_state s;
  s.p = {0.3, 1.2, 9.81};
  const auto disc = one_and_four(
      n, m, [&] { return disc_rhs(s); },
      [&](disc_rhs& f, std::size_t i, double* out) {
        std::array<double, m> dx;
        f(xs[i], dx, 0.0);
        std::memcpy(out, dx.data(), sizeof dx);
        return int(f.status());
      });
  CHECK(disc[11] == int(kane::solve_status::not_finite));
  CHECK(disc[0] == int(kane::solve_status::ok));

  // the driven 6R arm's forward dynamics and its derivatives: the recursive passes
  std::vector<arm_state> states(n);
  for (auto& a : states) {
    for (auto& v : a.q) v = 3 * unit(rng);
    for (auto& v : a.u) v = unit(rng);
    for (auto& v : a.r) v = 5 * unit(rng);
    a.qd = a.u;
  }
  states[5].q[2] = not_a_number;
  constexpr std::size_t k = 6 + 36 + 36;  // u', du'/dq, du'/du
  const auto arm = one_and_four(
      n, k, [] { return arm_evaluator{}; },
      [&](arm_evaluator& ev, std::size_t i, double* out) {
        ev.update(states[i]);
        const auto r = kane::forward_dynamics_derivatives<models::arm6::driven>(ev);
        std::memcpy(out, r.ud.data(), 6 * sizeof(double));
        std::memcpy(out + 6, r.dud_dq.data(), 36 * sizeof(double));
        std::memcpy(out + 42, r.dud_du.data(), 36 * sizeof(double));
        return int(r.status);
      });
  CHECK(arm[5] == int(kane::solve_status::not_finite));
  CHECK(arm[0] == int(kane::solve_status::ok));
}
