// Four small models' right-hand sides (small_models.hpp): kane as the README teaches it,
// beside hand-written closed forms and SymPy's generated C, each bare and checked as kane is
// (every input and output finite, else NaN and a status: ../common/checked.hpp).
#include <cmath>
#include <limits>
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

// all five agree on every state, with status 0; given a NaN, the checked ones and kane give NaN
// and status 1
template <int N, class F>
void agree(const std::vector<small::input<N>>& states, F kane, F hand, F sympy, F hand_checked,
           F sympy_checked) {
  for (const auto& in : states) {
    small::output<N> h{}, o{};
    hand(in, h);
    for (F f : {kane, sympy, hand_checked, sympy_checked}) {
      o.status = 0, f(in, o);
      bench::require_agreement(bench::max_diff(o.xd, h.xd, N));
    }
    for (F f : {kane, hand_checked, sympy_checked}) {
      o.status = -1, f(in, o);
      bench::require_agreement(o.status == 0 ? 0 : 1);
    }
  }
  small::input<N> bad = states[0];
  bad.x[N - 1] = std::numeric_limits<double>::quiet_NaN();
  for (F f : {kane, hand_checked, sympy_checked}) {
    small::output<N> o{};
    f(bad, o);
    bench::require_agreement(o.status == 1 && std::isnan(o.xd[0]) && std::isnan(o.xd[N - 1]) ? 0 : 1);
  }
}
void agree() {
  using namespace small;
  agree<6>(tops, top_kane, top_hand, top_sympy, top_hand_checked, top_sympy_checked);
  agree<14>(spacecrafts, spacecraft_kane, spacecraft_hand, spacecraft_sympy, spacecraft_hand_checked,
            spacecraft_sympy_checked);
  agree<4>(pendulums, pendulum_kane, pendulum_hand, pendulum_sympy, pendulum_hand_checked,
           pendulum_sympy_checked);
  agree<4>(pendulums, pendulum_absolute_kane, pendulum_absolute_hand, pendulum_absolute_sympy,
           pendulum_absolute_hand_checked, pendulum_absolute_sympy_checked);
}
}  // namespace

BENCHMARK(bench::run<small::top_hand, tops>)->Name("small/top/hand");
BENCHMARK(bench::run<small::top_hand_checked, tops>)->Name("small/top/hand_checked");
BENCHMARK(bench::run<small::top_sympy, tops>)->Name("small/top/sympy");
BENCHMARK(bench::run<small::top_sympy_checked, tops>)->Name("small/top/sympy_checked");
BENCHMARK(bench::run<small::top_kane, tops>)->Name("small/top/kane");
BENCHMARK(bench::run<small::spacecraft_hand, spacecrafts>)->Name("small/spacecraft/hand");
BENCHMARK(bench::run<small::spacecraft_hand_checked, spacecrafts>)->Name("small/spacecraft/hand_checked");
BENCHMARK(bench::run<small::spacecraft_sympy, spacecrafts>)->Name("small/spacecraft/sympy");
BENCHMARK(bench::run<small::spacecraft_sympy_checked, spacecrafts>)->Name("small/spacecraft/sympy_checked");
BENCHMARK(bench::run<small::spacecraft_kane, spacecrafts>)->Name("small/spacecraft/kane");
BENCHMARK(bench::run<small::pendulum_hand, pendulums>)->Name("small/pendulum/hand");
BENCHMARK(bench::run<small::pendulum_hand_checked, pendulums>)->Name("small/pendulum/hand_checked");
BENCHMARK(bench::run<small::pendulum_sympy, pendulums>)->Name("small/pendulum/sympy");
BENCHMARK(bench::run<small::pendulum_sympy_checked, pendulums>)->Name("small/pendulum/sympy_checked");
BENCHMARK(bench::run<small::pendulum_kane, pendulums>)->Name("small/pendulum/kane");
BENCHMARK(bench::run<small::pendulum_absolute_hand, pendulums>)->Name("small/pendulum_absolute/hand");
BENCHMARK(bench::run<small::pendulum_absolute_hand_checked, pendulums>)
    ->Name("small/pendulum_absolute/hand_checked");
BENCHMARK(bench::run<small::pendulum_absolute_sympy, pendulums>)->Name("small/pendulum_absolute/sympy");
BENCHMARK(bench::run<small::pendulum_absolute_sympy_checked, pendulums>)
    ->Name("small/pendulum_absolute/sympy_checked");
BENCHMARK(bench::run<small::pendulum_absolute_kane, pendulums>)->Name("small/pendulum_absolute/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
