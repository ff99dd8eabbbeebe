// The rolling disc's forward dynamics: kane (constrained_motion; and the reduced equations
// written out) beside the hand-written closed form and SymPy's generated code, each bare and
// checked as kane is (../common/checked.hpp).
#include <cmath>
#include <limits>
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
  using namespace disc_dynamics;
  for (const auto& in : states) {
    output h{}, o{};
    hand_rates(in, h);
    for (auto f : {kane_rates, kane_reduced_rates, sympy_rates, hand_rates_checked, sympy_rates_checked}) {
      o.status = 0, f(in, o);
      bench::require_agreement(bench::max_diff(o.xd, h.xd, 8));
    }
    for (auto f : {kane_rates, hand_rates_checked, sympy_rates_checked}) {
      o.status = -1, f(in, o);
      bench::require_agreement(o.status == 0 ? 0 : 1);
    }
  }
  input bad = states[0];
  bad.x[7] = std::numeric_limits<double>::quiet_NaN();
  for (auto f : {kane_rates, hand_rates_checked, sympy_rates_checked}) {
    output o{};
    f(bad, o);
    bench::require_agreement(o.status == 1 && std::isnan(o.xd[0]) && std::isnan(o.xd[7]) ? 0 : 1);
  }
}
}  // namespace

BENCHMARK(bench::run<disc_dynamics::hand_rates, states>)->Name("disc_dynamics/forward/hand");
BENCHMARK(bench::run<disc_dynamics::hand_rates_checked, states>)->Name("disc_dynamics/forward/hand_checked");
BENCHMARK(bench::run<disc_dynamics::sympy_rates, states>)->Name("disc_dynamics/forward/sympy");
BENCHMARK(bench::run<disc_dynamics::sympy_rates_checked, states>)
    ->Name("disc_dynamics/forward/sympy_checked");
BENCHMARK(bench::run<disc_dynamics::kane_rates, states>)->Name("disc_dynamics/forward/kane");
BENCHMARK(bench::run<disc_dynamics::kane_reduced_rates, states>)->Name("disc_dynamics/forward/kane_reduced");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
