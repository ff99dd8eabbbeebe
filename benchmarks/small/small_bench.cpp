// Three small models' right-hand sides (small_models.hpp): kane as the README teaches it,
// beside hand-written closed forms and SymPy's generated C.
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "small_models.hpp"

namespace {
template <int N>
std::vector<small::input<N>> inputs(unsigned seed, void (*fix)(small::input<N>&, std::mt19937&)) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<small::input<N>> in(64);
  for (auto& s : in) {
    for (double& x : s.x) x = d(rng);
    fix(s, rng);
  }
  return in;
}
const auto tops = inputs<6>(3, [](small::top_in& s, std::mt19937& rng) {
  s.x[1] = std::uniform_real_distribution<double>(0.3, 2.8)(rng);  // away from the 3-1-3 singularity
});
const auto spacecrafts = inputs<14>(5, [](small::spacecraft_in& s, std::mt19937&) {
  const double n = std::sqrt(s.x[0] * s.x[0] + s.x[1] * s.x[1] + s.x[2] * s.x[2] + s.x[3] * s.x[3]);
  for (int i = 0; i < 4; ++i) s.x[i] /= n;  // a unit quaternion
});
const auto pendulums = inputs<4>(7, [](small::pendulum_in&, std::mt19937&) {});

template <int N, class F>
void agree(const std::vector<small::input<N>>& states, F kane, F hand, F sympy) {
  for (const auto& in : states) {
    small::output<N> k{}, h{}, s{};
    kane(in, k), hand(in, h), sympy(in, s);
    bench::require_agreement(std::fmax(bench::max_diff(k.xd, h.xd, N), bench::max_diff(s.xd, h.xd, N)));
  }
}
void agree() {
  agree<6>(tops, small::top_kane, small::top_hand, small::top_sympy);
  agree<14>(spacecrafts, small::spacecraft_kane, small::spacecraft_hand, small::spacecraft_sympy);
  agree<4>(pendulums, small::pendulum_kane, small::pendulum_hand, small::pendulum_sympy);
}
}  // namespace

BENCHMARK(bench::run<small::top_hand, tops>)->Name("small/top/hand");
BENCHMARK(bench::run<small::top_sympy, tops>)->Name("small/top/sympy");
BENCHMARK(bench::run<small::top_kane, tops>)->Name("small/top/kane");
BENCHMARK(bench::run<small::spacecraft_hand, spacecrafts>)->Name("small/spacecraft/hand");
BENCHMARK(bench::run<small::spacecraft_sympy, spacecrafts>)->Name("small/spacecraft/sympy");
BENCHMARK(bench::run<small::spacecraft_kane, spacecrafts>)->Name("small/spacecraft/kane");
BENCHMARK(bench::run<small::pendulum_hand, pendulums>)->Name("small/pendulum/hand");
BENCHMARK(bench::run<small::pendulum_sympy, pendulums>)->Name("small/pendulum/sympy");
BENCHMARK(bench::run<small::pendulum_kane, pendulums>)->Name("small/pendulum/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
