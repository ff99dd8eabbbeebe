// The rolling disc's forward dynamics: kane (constrained_motion; and the reduced equations
// written out) beside the hand-written closed form and SymPy's generated code.
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "disc_dynamics.hpp"

const disc_dynamics::params disc_dynamics::p = {0.3, 1.2, 9.81};

namespace {
std::vector<disc_dynamics::input> inputs() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-3, 3), lean(-1.2, 1.2);
  std::vector<disc_dynamics::input> in(64);
  for (auto& s : in) {
    for (double& x : s.x) x = d(rng);
    s.x[1] = lean(rng);
  }
  return in;
}
const std::vector<disc_dynamics::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    disc_dynamics::output k{}, l{}, h{}, s{};
    disc_dynamics::kane_rates(in, k);
    disc_dynamics::kane_reduced_rates(in, l);
    disc_dynamics::hand_rates(in, h);
    disc_dynamics::sympy_rates(in, s);
    const double kane = std::fmax(bench::max_diff(k.xd, h.xd, 8), bench::max_diff(l.xd, h.xd, 8));
    bench::require_agreement(std::fmax(kane, bench::max_diff(s.xd, h.xd, 8)));
  }
}
}  // namespace

BENCHMARK(bench::run<disc_dynamics::hand_rates, states>)->Name("disc_dynamics/forward/hand");
BENCHMARK(bench::run<disc_dynamics::sympy_rates, states>)->Name("disc_dynamics/forward/sympy");
BENCHMARK(bench::run<disc_dynamics::kane_rates, states>)->Name("disc_dynamics/forward/kane");
BENCHMARK(bench::run<disc_dynamics::kane_reduced_rates, states>)->Name("disc_dynamics/forward/kane_reduced");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
