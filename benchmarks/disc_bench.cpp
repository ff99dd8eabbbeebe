// kane beside the hand-written rolling disc, one binary; outputs agree to
// 1e-12 before anything is timed. Inputs cycle over 64 random states.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

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

void agree_or_exit() {
  for (const auto& in : states) {
    disc::output k{}, h{};
    disc::kane_partials(in, k);
    disc::hand_partials(in, h);
    double d = 0;
    for (int i = 0; i < 6; ++i) d = std::fmax(d, std::fabs(k.A[i] - h.A[i]));
    for (int i = 0; i < 9; ++i) d = std::fmax(d, std::fabs(k.V[i] - h.V[i]));
    if (!(d <= 1e-12)) {
      std::fprintf(stderr, "kane and hand-written disagree by %g\n", d);
      std::exit(1);
    }
  }
}

template <void (*F)(const disc::input&, disc::output&)>
void run(benchmark::State& st) {
  disc::output out{};
  std::size_t i = 0;
  for (auto _ : st) {
    F(states[i++ & 63], out);
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
}
}  // namespace

BENCHMARK(run<disc::hand_partials>)->Name("disc/nonholonomic_partials/hand");
BENCHMARK(run<disc::kane_partials>)->Name("disc/nonholonomic_partials/kane");

int main(int argc, char** argv) {
  agree_or_exit();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
