// What every benchmark binary shares: outputs agree to 1e-12 before anything
// is timed, and inputs cycle over 64 states.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace bench {

inline double max_diff(const double* a, const double* b, int n) {
  double m = 0;
  for (int i = 0; i < n; ++i) m = std::fmax(m, std::fabs(a[i] - b[i]));
  return m;
}

inline void require_agreement(double difference) {
  if (!(difference <= 1e-12)) {
    std::fprintf(stderr, "implementations disagree by %g (beyond 1e-12)\n", difference);
    std::exit(1);
  }
}

template <class In, class Out>
Out output_of(void (*)(const In&, Out&));

// Times F over the 64 states of States.
template <auto F, const auto& States>
void run(benchmark::State& st) {
  decltype(output_of(F)) out{};
  std::size_t i = 0;
  for (auto _ : st) {
    F(States[i++ & 63], out);
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
}

inline int main(int argc, char** argv, void (*agree)()) {
  agree();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace bench
