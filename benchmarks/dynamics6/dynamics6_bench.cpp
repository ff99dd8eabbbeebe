// Forward and inverse dynamics of the 6-revolute chain with link masses: kane beside a
// hand-written CRBA + RNEA + LLT (RNEA for tau) and Orocos KDL's ChainDynParam + LLT
// (ChainIdSolver_RNE for tau).
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "dynamics6.hpp"

namespace {
std::vector<dynamics6::input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<dynamics6::input> in(64);
  for (auto& x : in)
    for (int i = 0; i < 6; ++i) x.q[i] = d(rng), x.qd[i] = d(rng);
  for (auto& x : in)  // after q and q', which stay the states they were
    for (int i = 0; i < 6; ++i) x.qdd_in[i] = d(rng);
  return in;
}
const std::vector<dynamics6::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    dynamics6::output k{}, h{}, o{}, kb{};
    dynamics6::kane_forward(in, k);  // q'' alone
    dynamics6::kane_bias(in, kb);    // M and h
    dynamics6::hand_forward(in, h);
    dynamics6::kdl_forward(in, o);
    bench::require_agreement(std::fmax(bench::max_diff(kb.M, h.M, 42), bench::max_diff(o.M, h.M, 48)));
    bench::require_agreement(bench::max_diff(k.qdd, h.qdd, 6));
    dynamics6::output m{};  // kane's M alone (a pose-level evaluator)
    dynamics6::kane_mass(in, m);
    bench::require_agreement(bench::max_diff(m.M, h.M, 36));
    dynamics6::output kt{}, ht{}, ot{};  // tau alone, and tau = M q''_in + h from hand's M and h
    dynamics6::kane_inverse(in, kt);
    dynamics6::hand_inverse(in, ht);
    dynamics6::kdl_inverse(in, ot);
    double tau[6];
    for (int i = 0; i < 6; ++i) {
      tau[i] = h.h[i];
      for (int j = 0; j < 6; ++j) tau[i] += h.M[6 * j + i] * in.qdd_in[j];
    }
    bench::require_agreement(
        std::fmax(bench::max_diff(kt.tau, ht.tau, 6), bench::max_diff(ot.tau, ht.tau, 6)));
    bench::require_agreement(bench::max_diff(tau, ht.tau, 6));
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
BENCHMARK(bench::run<dynamics6::hand_inverse, states>)->Name("dynamics6/inverse/hand");
BENCHMARK(bench::run<dynamics6::kane_inverse, states>)->Name("dynamics6/inverse/kane");
BENCHMARK(bench::run<dynamics6::kdl_inverse, states>)->Name("dynamics6/inverse/kdl");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
