// kane beside the hand-written outward pass for chains of 2 to 20 joints.
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "chain.hpp"

namespace {
std::vector<chain::input> inputs() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<chain::input> in(64);
  for (auto& x : in)
    for (int i = 0; i < chain::max_n; ++i) x.q[i] = d(rng), x.qd[i] = d(rng), x.qdd[i] = d(rng);
  return in;
}
const std::vector<chain::input> states = inputs();

template <int n>
void agree_n() {
  for (const auto& in : states) {
    chain::output k{}, h{};
    chain::kane_all<n>(in, k);
    chain::hand_all<n>(in, h);
    bench::require_agreement(bench::max_diff(k.R, h.R, 18 + 6 * n));
  }
}
void agree() { agree_n<2>(), agree_n<4>(), agree_n<6>(), agree_n<10>(), agree_n<16>(), agree_n<20>(); }
}  // namespace

#define KANE_CHAIN(n)                                                               \
  BENCHMARK(bench::run<chain::hand_all<n>, states>)->Name("chain/" #n "/ALL/hand"); \
  BENCHMARK(bench::run<chain::kane_all<n>, states>)->Name("chain/" #n "/ALL/kane")
KANE_CHAIN(2);
KANE_CHAIN(4);
KANE_CHAIN(6);
KANE_CHAIN(10);
KANE_CHAIN(16);
KANE_CHAIN(20);

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
