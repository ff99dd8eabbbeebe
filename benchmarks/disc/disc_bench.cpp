// kane beside the hand-written and the SymPy-generated rolling disc.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "disc.hpp"

namespace {
std::vector<disc::input> inputs() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.2, 1.2);
  std::vector<disc::input> in(64);
  for (auto& x : in) {
    for (int i = 0; i < 5; ++i) x.q[i] = d(rng), x.u[i] = d(rng);
    x.r = 0.3;
  }
  return in;
}
const std::vector<disc::input> states = inputs();

// all four agree with status 0; given a NaN, kane and the checked hand code give NaN and status 1
void agree() {
  const auto diff = [](const disc::output& a, const disc::output& b) {
    return std::fmax(bench::max_diff(a.A, b.A, 6), bench::max_diff(a.V, b.V, 9));
  };
  for (const auto& in : states) {
    disc::output k{}, h{}, c{}, s{};
    disc::kane_partials(in, k);
    disc::hand_partials(in, h);
    disc::hand_partials_checked(in, c);
    disc::sympy_partials(in, s);
    bench::require_agreement(std::fmax(std::fmax(diff(k, h), diff(s, h)), diff(c, h)));
    bench::require_agreement(k.status + c.status);
  }
  disc::input bad = states[0];
  bad.q[1] = std::numeric_limits<double>::quiet_NaN();
  for (const auto f : {disc::kane_partials, disc::hand_partials_checked}) {
    disc::output o{};
    f(bad, o);
    bench::require_agreement(o.status == 1 && std::isnan(o.A[0]) && std::isnan(o.V[0]) ? 0 : 1);
  }
}
}  // namespace

BENCHMARK(bench::run<disc::hand_partials, states>)->Name("disc/nonholonomic_partials/hand");
BENCHMARK(bench::run<disc::hand_partials_checked, states>)->Name("disc/nonholonomic_partials/hand_checked");
BENCHMARK(bench::run<disc::kane_partials, states>)->Name("disc/nonholonomic_partials/kane");
BENCHMARK(bench::run<disc::sympy_partials, states>)->Name("disc/nonholonomic_partials/sympy");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
