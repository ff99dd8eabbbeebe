// kane beside the hand-written outward pass, one binary; outputs agree to
// 1e-12 before anything is timed. Inputs cycle over 64 random states.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "arm6.hpp"

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

double max_diff(const double* a, const double* b, int n) {
  double m = 0;
  for (int i = 0; i < n; ++i) m = std::fmax(m, std::fabs(a[i] - b[i]));
  return m;
}

void agree_or_exit() {
  for (const auto& in : states) {
    arm6::output k{}, h{}, kp{}, hp{};
    arm6::kane_all(in, k);
    arm6::hand_all(in, h);
    arm6::kane_pose(in, kp);
    arm6::hand_pose(in, hp);
    const double d = std::fmax(max_diff(&k.R[0], &h.R[0], 24),
                               std::fmax(max_diff(kp.R, hp.R, 9), max_diff(kp.p, hp.p, 3)));
    if (!(d <= 1e-12)) {
      std::fprintf(stderr, "kane and hand-written disagree by %g\n", d);
      std::exit(1);
    }
  }
}

template <void (*F)(const arm6::input&, arm6::output&)>
void run(benchmark::State& st) {
  arm6::output out{};
  std::size_t i = 0;
  for (auto _ : st) {
    F(states[i++ & 63], out);
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
}
}  // namespace

BENCHMARK(run<arm6::hand_pose>)->Name("arm6/pose/hand");
BENCHMARK(run<arm6::kane_pose>)->Name("arm6/pose/kane");
BENCHMARK(run<arm6::hand_all>)->Name("arm6/all/hand");
BENCHMARK(run<arm6::kane_all>)->Name("arm6/all/kane");

int main(int argc, char** argv) {
  agree_or_exit();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
