// Forward dynamics of the 6-revolute chain with link masses: kane beside a
// hand-written CRBA + RNEA + LLT and Orocos KDL's ChainDynParam + LLT.
#include <random>
#include <vector>

#include "dynamics6.hpp"
#include "harness.hpp"

namespace {
std::vector<dynamics6::input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<dynamics6::input> in(64);
  for (auto& x : in)
    for (int i = 0; i < 6; ++i) x.q[i] = d(rng), x.qd[i] = d(rng);
  return in;
}
const std::vector<dynamics6::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    dynamics6::output k{}, h{}, o{};
    dynamics6::kane_forward(in, k);
    dynamics6::hand_forward(in, h);
    dynamics6::kdl_forward(in, o);
    const int n = sizeof(dynamics6::output) / sizeof(double);
    bench::require_agreement(std::fmax(bench::max_diff(k.M, h.M, n), bench::max_diff(o.M, h.M, n)));
    dynamics6::output m{};  // kane's M alone (a pose-level evaluator)
    dynamics6::kane_mass(in, m);
    bench::require_agreement(bench::max_diff(m.M, h.M, 36));
  }
}
}  // namespace

BENCHMARK(bench::run<dynamics6::hand_mass, states>)->Name("dynamics6/M/hand");
BENCHMARK(bench::run<dynamics6::kane_mass, states>)->Name("dynamics6/M/kane");
BENCHMARK(bench::run<dynamics6::kdl_mass, states>)->Name("dynamics6/M/kdl");
BENCHMARK(bench::run<dynamics6::hand_bias, states>)->Name("dynamics6/M_and_bias/hand");
BENCHMARK(bench::run<dynamics6::kane_bias, states>)->Name("dynamics6/M_and_bias/kane");
BENCHMARK(bench::run<dynamics6::kdl_bias, states>)->Name("dynamics6/M_and_bias/kdl");
BENCHMARK(bench::run<dynamics6::hand_forward, states>)->Name("dynamics6/forward/hand");
BENCHMARK(bench::run<dynamics6::kane_forward, states>)->Name("dynamics6/forward/kane");
BENCHMARK(bench::run<dynamics6::kdl_forward, states>)->Name("dynamics6/forward/kdl");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
