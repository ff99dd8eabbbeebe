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
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
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
  std::vector<double> one(n * m), four(n * m);
  std::vector<int> status_one(n), status_four(n);
  const auto make_disc = [&] { return disc_rhs(s); };
  const auto disc = [&](disc_rhs& f, std::size_t i, std::vector<double>& out, std::vector<int>& status) {
    std::array<double, m> dx;
    f(xs[i], dx, 0.0);
    std::memcpy(&out[i * m], dx.data(), sizeof dx);
    status[i] = int(f.status());
  };
  split(n, 1, make_disc, [&](disc_rhs& f, std::size_t i) { disc(f, i, one, status_one); });
  split(n, 4, make_disc, [&](disc_rhs& f, std::size_t i) { disc(f, i, four, status_four); });
  CHECK(same_bits(one, four));
  CHECK(status_one == status_four);
  CHECK(status_one[11] == int(kane::solve_status::not_finite));
  CHECK(status_one[0] == int(kane::solve_status::ok));

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
  std::vector<double> arm_one(n * k), arm_four(n * k);
  std::vector<int> arm_status_one(n), arm_status_four(n);
  const auto make_arm = [] { return arm_evaluator{}; };
  const auto arm = [&](arm_evaluator& ev, std::size_t i, std::vector<double>& out, std::vector<int>& status) {
    ev.update(states[i]);
    const auto r = kane::forward_dynamics_derivatives<models::arm6::driven>(ev);
    std::memcpy(&out[i * k], r.ud.data(), 6 * sizeof(double));
    std::memcpy(&out[i * k + 6], r.dud_dq.data(), 36 * sizeof(double));
    std::memcpy(&out[i * k + 42], r.dud_du.data(), 36 * sizeof(double));
    status[i] = int(r.status);
  };
  split(n, 1, make_arm, [&](arm_evaluator& ev, std::size_t i) { arm(ev, i, arm_one, arm_status_one); });
  split(n, 4, make_arm, [&](arm_evaluator& ev, std::size_t i) { arm(ev, i, arm_four, arm_status_four); });
  CHECK(same_bits(arm_one, arm_four));
  CHECK(arm_status_one == arm_status_four);
  CHECK(arm_status_one[5] == int(kane::solve_status::not_finite));
  CHECK(arm_status_one[0] == int(kane::solve_status::ok));
}
