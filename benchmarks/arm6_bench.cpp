// kane beside the hand-written outward pass for the 6-revolute chain.
#include <random>
#include <vector>

#include "arm6.hpp"
#include "harness.hpp"

namespace {
std::vector<arm6::input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<arm6::input> in(64);
  for (auto& x : in)
    for (int i = 0; i < 6; ++i) x.q[i] = d(rng), x.qd[i] = d(rng), x.qdd[i] = d(rng);
  return in;
}
const std::vector<arm6::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    arm6::output k{}, h{}, kp{}, hp{};
    arm6::kane_all(in, k);
    arm6::hand_all(in, h);
    arm6::kane_pose(in, kp);
    arm6::hand_pose(in, hp);
    bench::require_agreement(
        std::fmax(bench::max_diff(&k.R[0], &h.R[0], 24),
                  std::fmax(bench::max_diff(kp.R, hp.R, 9), bench::max_diff(kp.p, hp.p, 3))));
  }
}
}  // namespace

BENCHMARK(bench::run<arm6::hand_pose, states>)->Name("arm6/pose/hand");
BENCHMARK(bench::run<arm6::kane_pose, states>)->Name("arm6/pose/kane");
BENCHMARK(bench::run<arm6::hand_all, states>)->Name("arm6/all/hand");
BENCHMARK(bench::run<arm6::kane_all, states>)->Name("arm6/all/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
