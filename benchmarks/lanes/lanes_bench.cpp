// Many states per call (lanes_models.hpp): 64 states of each small model per row, by the hand
// and SymPy functions state by state, kane's scalar path, and kane's lanes of 4 and 8 doubles and
// 16 floats (8 and 16 where KANE_LANES_WIDE). The states are those of ../small/small_bench.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "../../examples/models/bicycle.hpp"
#include "../common/harness.hpp"
#include "lanes_models.hpp"

const disc_dynamics::params disc_dynamics::p = {0.3, 1.2, 9.81};
const std::array<double, 27> bicycle::p = [] {
  std::array<double, 27> out{};
  const auto s = models::bicycle::benchmark_parameters();
  for (std::size_t i = 0; i < 27; ++i) out[i] = s.p[i];
  return out;
}();

// The group of the rows: lanes, or lanes_avx2 for the binary built without AVX-512
#ifndef KANE_LANES_GROUP
#define KANE_LANES_GROUP "lanes"
#endif

// the rows of 8 doubles (after a comma) and of 16 floats, where built
#if KANE_LANES_WIDE
#define KANE_X8(f) , f##_x8
#define KANE_X16(f) f##_float_x16
#else
#define KANE_X8(f)
#define KANE_X16(f) nullptr
#endif

namespace {
template <int N>
std::vector<small::input<N>> inputs(unsigned seed, void (*fix)(small::input<N>&, std::mt19937&)) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<small::input<N>> in(lanes_bench::batch);
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
const auto arms = [] {  // as ../dynamics6/dynamics6_bench.cpp
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<dynamics6::input> in(lanes_bench::batch);
  for (auto& x : in)
    for (int i = 0; i < 6; ++i) x.q[std::size_t(i)] = d(rng), x.qd[std::size_t(i)] = d(rng);
  return in;
}();

template <class In, class Out>
In input_of(void (*)(const In&, Out&));
template <class In, class Out>
Out output_of(void (*)(const In*, Out*));
const auto discs = [] {  // as ../disc_dynamics/disc_dynamics_bench.cpp
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-3, 3), lean(-1.2, 1.2);
  std::vector<disc_dynamics::input> in(lanes_bench::batch);
  for (auto& s : in) {
    for (double& x : s.x) x = d(rng);
    s.x[1] = lean(rng);
  }
  return in;
}();
const auto bicycles = [] {  // as ../bicycle/bicycle_bench.cpp: the pitch closes the constraint
  namespace b = models::bicycle;
  std::mt19937 rng(2007);
  std::uniform_real_distribution<double> xy(-2, 2), yaw(-M_PI, M_PI), angle(-0.5, 0.5), rate(-1, 1), v(2, 8);
  std::vector<bicycle::input> in(lanes_bench::batch);
  for (auto& x : in) {
    b::dynamics_state s = b::benchmark_parameters();
    s.q = {xy(rng), xy(rng), yaw(rng), angle(rng), 0.0, angle(rng)};
    b::dynamics_evaluator ev;
    if (kane::solve_configuration<b::pitch>(ev, s).status != kane::solve_status::ok)
      bench::require_agreement(1);
    for (std::size_t i = 0; i < 6; ++i) x.x[i] = s.q[i];
    x.x[6] = rate(rng), x.x[7] = rate(rng), x.x[8] = v(rng) / s.p[1];
  }
  return in;
}();
const auto chains = [] {  // as ../chain_dynamics/chain_dynamics_bench.cpp
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<chain_dynamics::input> in(lanes_bench::batch);
  for (auto& x : in)
    for (std::size_t i = 0; i < chain_dynamics::max_n; ++i)
      x.q[i] = d(rng), x.qd[i] = d(rng), x.qdd[i] = d(rng);
  return in;
}();

// One state's function over the batch
template <auto F>
void each(const decltype(input_of(F))* in, decltype(bench::output_of(F))* out) {
  for (int i = 0; i < lanes_bench::batch; ++i) F(in[i], out[i]);
}
// Times F over the batch States (64 states an iteration).
template <auto F, const auto& States>
void run(benchmark::State& st) {
  std::array<decltype(output_of(F)), lanes_bench::batch> out{};
  for (auto _ : st) {
    F(States.data(), out.data());
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
}

// Every kane batch agrees with the hand code: doubles to 1e-12, floats to 1e-4 relative; every
// status 0.
template <int N>
void agree(const std::vector<small::input<N>>& states,
           void (*hand)(const small::input<N>&, small::output<N>&),
           std::initializer_list<lanes_bench::batch_function<N>> doubles,
           lanes_bench::batch_function<N> floats) {
  std::array<small::output<N>, lanes_bench::batch> h{}, o{};
  for (int i = 0; i < lanes_bench::batch; ++i) hand(states[std::size_t(i)], h[std::size_t(i)]);
  for (auto f : doubles) {
    f(states.data(), o.data());
    for (int i = 0; i < lanes_bench::batch; ++i) {
      bench::require_agreement(bench::max_diff(o[std::size_t(i)].xd, h[std::size_t(i)].xd, N));
      bench::require_agreement(o[std::size_t(i)].status);
    }
  }
  if (!floats) return;
  floats(states.data(), o.data());
  for (int i = 0; i < lanes_bench::batch; ++i)
    for (int k = 0; k < N; ++k) {
      const double a = o[std::size_t(i)].xd[k], b = h[std::size_t(i)].xd[k];
      bench::require_agreement(std::abs(a - b) <= 1e-4 * (1 + std::abs(b)) ? 0 : 1);
    }
}
// Batches of N-entry x' against the batch ref: doubles to tol times the largest |x'| of a state (at
// least 1), floats to 1e-3.
template <int N, class In, class Out>
void outputs_agree(const std::vector<In>& states, void (*ref)(const In*, Out*),
                   std::initializer_list<void (*)(const In*, Out*)> doubles,
                   std::type_identity_t<void (*)(const In*, Out*)> floats, double tol) {
  std::array<Out, lanes_bench::batch> h{}, o{};
  ref(states.data(), h.data());
  const auto check = [&](double t) {
    for (std::size_t i = 0; i < h.size(); ++i) {
      double scale = 1;
      for (int k = 0; k < N; ++k) scale = std::max(scale, std::abs(h[i].xd[k]));
      bench::require_agreement(bench::max_diff(o[i].xd, h[i].xd, N) <= t * scale ? 0 : 1);
    }
  };
  for (auto f : doubles) f(states.data(), o.data()), check(tol);
  if (floats) floats(states.data(), o.data()), check(1e-3);
}
// The x' of the lanes from structure-of-arrays buffers against the scalar path's (1e-12 relative),
// every status 0
template <int N>
void soa_agree(const std::vector<small::input<N>>& states, lanes_bench::batch_function<N> scalar,
               const void* (*soa)(const small::input<N>*), void (*out)(small::output<N>*)) {
  std::array<small::output<N>, lanes_bench::batch> h{}, o{};
  scalar(states.data(), h.data());
  soa(states.data());
  out(o.data());
  for (std::size_t i = 0; i < h.size(); ++i) {
    double scale = 1;
    for (int k = 0; k < N; ++k) scale = std::max(scale, std::abs(h[i].xd[k]));
    bench::require_agreement(bench::max_diff(o[i].xd, h[i].xd, N) / scale);
    bench::require_agreement(o[i].status);
  }
}
void agree() {
  using namespace lanes_bench;
  soa_agree<6>(tops, top_kane, top_kane_soa, top_soa_out);
  soa_agree<14>(spacecrafts, spacecraft_kane, spacecraft_kane_soa, spacecraft_soa_out);
  soa_agree<4>(pendulums, pendulum_absolute_kane, pendulum_absolute_kane_soa, pendulum_absolute_soa_out);
  agree<6>(tops, small::top_hand, {top_kane, top_kane_x4 KANE_X8(top_kane)}, KANE_X16(top_kane));
  agree<14>(spacecrafts, small::spacecraft_hand,
            {spacecraft_kane, spacecraft_kane_x4 KANE_X8(spacecraft_kane)}, KANE_X16(spacecraft_kane));
  agree<4>(pendulums, small::pendulum_absolute_hand,
           {pendulum_absolute_kane, pendulum_absolute_kane_x4 KANE_X8(pendulum_absolute_kane)},
           KANE_X16(pendulum_absolute_kane));
  std::array<dynamics6::output, batch> h{}, o{};
  each<dynamics6::hand_forward>(arms.data(), h.data());
  for (auto f : {arm6_forward_kane, arm6_forward_kane_x4 KANE_X8(arm6_forward_kane)}) {
    f(arms.data(), o.data());
    for (std::size_t i = 0; i < h.size(); ++i)
      bench::require_agreement(bench::max_diff(o[i].qdd, h[i].qdd, 6));
  }
#if KANE_LANES_WIDE
  arm6_forward_kane_float_x16(arms.data(), o.data());
  for (std::size_t i = 0; i < h.size(); ++i)
    for (int k = 0; k < 6; ++k)
      bench::require_agreement(std::abs(o[i].qdd[k] - h[i].qdd[k]) <= 1e-3 * (1 + std::abs(h[i].qdd[k])) ? 0
                                                                                                         : 1);
#endif
  std::array<arm6_derivatives, batch> dh{}, dl{};  // the derivatives relative to their largest
  arm6_derivatives_kane(arms.data(), dh.data());
  for (auto f : {arm6_derivatives_kane_x4 KANE_X8(arm6_derivatives_kane)}) {
    f(arms.data(), dl.data());
    for (std::size_t i = 0; i < dh.size(); ++i) {
      double scale = 1;
      for (int k = 0; k < 36; ++k) scale = std::max({scale, std::abs(dh[i].dq[k]), std::abs(dh[i].dqd[k])});
      bench::require_agreement(
          bench::max_diff(dl[i].qdd, h[i].qdd, 6) +
          std::max(bench::max_diff(dl[i].dq, dh[i].dq, 36), bench::max_diff(dl[i].dqd, dh[i].dqd, 36)) /
              scale);
    }
  }

  outputs_agree<8>(discs, each<disc_dynamics::hand_rates>, {disc_kane, disc_kane_x4 KANE_X8(disc_kane)},
                   KANE_X16(disc_kane), 1e-12);
  outputs_agree<9>(bicycles, each<bicycle::sympy_rates>,
                   {bicycle_kane, bicycle_kane_x4 KANE_X8(bicycle_kane)}, KANE_X16(bicycle_kane), 1e-10);
  std::array<chain_dynamics::output, batch> ch{}, co{};
  each<chain_dynamics::hand_forward<24>>(chains.data(), ch.data());
  for (auto f : {chain24_forward_kane, chain24_forward_kane_x4 KANE_X8(chain24_forward_kane)}) {
    f(chains.data(), co.data());
    for (std::size_t i = 0; i < ch.size(); ++i)
      bench::require_agreement(bench::max_diff(co[i].qdd, ch[i].qdd, 24) * 1e-3);
  }
}
}  // namespace

#define KANE_LANES_ROWS(model, states)                                                                      \
  BENCHMARK(run<each<small::model##_hand>, states>)->Name(KANE_LANES_GROUP "/" #model "/hand");             \
  BENCHMARK(run<each<small::model##_sympy>, states>)->Name(KANE_LANES_GROUP "/" #model "/sympy");           \
  BENCHMARK(run<each<small::model##_sympy_checked>, states>)                                                \
      ->Name(KANE_LANES_GROUP "/" #model "/sympy_checked");                                                 \
  BENCHMARK(run<lanes_bench::model##_kane, states>)->Name(KANE_LANES_GROUP "/" #model "/kane");             \
  BENCHMARK(run<lanes_bench::model##_kane_x4, states>)->Name(KANE_LANES_GROUP "/" #model "/kane_x4");       \
  BENCHMARK(run_soa<lanes_bench::model##_kane_soa, states>)->Name(KANE_LANES_GROUP "/" #model "/kane_soa"); \
  KANE_LANES_WIDE_ROWS(model, states)
// F over the batch in structure-of-arrays buffers (lanes_models.hpp)
template <auto F, const auto& States>
void run_soa(benchmark::State& st) {
  for (auto _ : st) {
    benchmark::DoNotOptimize(F(States.data()));
    benchmark::ClobberMemory();
  }
}
#if KANE_LANES_WIDE
#define KANE_LANES_WIDE_ROWS(model, states)                                                           \
  BENCHMARK(run<lanes_bench::model##_kane_x8, states>)->Name(KANE_LANES_GROUP "/" #model "/kane_x8"); \
  BENCHMARK(run<lanes_bench::model##_kane_float_x16, states>)                                         \
      ->Name(KANE_LANES_GROUP "/" #model "/kane_float_x16")
#else
#define KANE_LANES_WIDE_ROWS(model, states) static_assert(true)
#endif

KANE_LANES_ROWS(top, tops);
KANE_LANES_ROWS(spacecraft, spacecrafts);
KANE_LANES_ROWS(pendulum_absolute, pendulums);
BENCHMARK(run<each<dynamics6::hand_forward>, arms>)->Name(KANE_LANES_GROUP "/arm6_forward/hand");
BENCHMARK(run<lanes_bench::arm6_forward_kane, arms>)->Name(KANE_LANES_GROUP "/arm6_forward/kane");
BENCHMARK(run<lanes_bench::arm6_forward_kane_x4, arms>)->Name(KANE_LANES_GROUP "/arm6_forward/kane_x4");
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::arm6_forward_kane_x8, arms>)->Name(KANE_LANES_GROUP "/arm6_forward/kane_x8");
#endif
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::arm6_forward_kane_float_x16, arms>)
    ->Name(KANE_LANES_GROUP "/arm6_forward/kane_float_x16");
#endif
BENCHMARK(run<lanes_bench::arm6_derivatives_kane, arms>)->Name(KANE_LANES_GROUP "/arm6_derivatives/kane");
BENCHMARK(run<lanes_bench::arm6_derivatives_kane_x4, arms>)
    ->Name(KANE_LANES_GROUP "/arm6_derivatives/kane_x4");
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::arm6_derivatives_kane_x8, arms>)
    ->Name(KANE_LANES_GROUP "/arm6_derivatives/kane_x8");
#endif
BENCHMARK(run<each<chain_dynamics::hand_forward<24>>, chains>)
    ->Name(KANE_LANES_GROUP "/chain24_forward/hand");
BENCHMARK(run<lanes_bench::chain24_forward_kane, chains>)->Name(KANE_LANES_GROUP "/chain24_forward/kane");
BENCHMARK(run<lanes_bench::chain24_forward_kane_x4, chains>)
    ->Name(KANE_LANES_GROUP "/chain24_forward/kane_x4");
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::chain24_forward_kane_x8, chains>)
    ->Name(KANE_LANES_GROUP "/chain24_forward/kane_x8");
#endif
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::chain24_forward_kane_float_x16, chains>)
    ->Name(KANE_LANES_GROUP "/chain24_forward/kane_float_x16");
#endif
BENCHMARK(run<each<disc_dynamics::hand_rates>, discs>)->Name(KANE_LANES_GROUP "/disc/hand");
BENCHMARK(run<each<disc_dynamics::sympy_rates>, discs>)->Name(KANE_LANES_GROUP "/disc/sympy");
BENCHMARK(run<each<disc_dynamics::sympy_rates_checked>, discs>)->Name(KANE_LANES_GROUP "/disc/sympy_checked");
BENCHMARK(run<lanes_bench::disc_kane, discs>)->Name(KANE_LANES_GROUP "/disc/kane");
BENCHMARK(run<lanes_bench::disc_kane_x4, discs>)->Name(KANE_LANES_GROUP "/disc/kane_x4");
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::disc_kane_x8, discs>)->Name(KANE_LANES_GROUP "/disc/kane_x8");
#endif
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::disc_kane_float_x16, discs>)->Name(KANE_LANES_GROUP "/disc/kane_float_x16");
#endif
BENCHMARK(run<each<bicycle::sympy_rates>, bicycles>)->Name(KANE_LANES_GROUP "/bicycle/sympy");
BENCHMARK(run<lanes_bench::bicycle_kane, bicycles>)->Name(KANE_LANES_GROUP "/bicycle/kane");
BENCHMARK(run<lanes_bench::bicycle_kane_x4, bicycles>)->Name(KANE_LANES_GROUP "/bicycle/kane_x4");
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::bicycle_kane_x8, bicycles>)->Name(KANE_LANES_GROUP "/bicycle/kane_x8");
#endif
#if KANE_LANES_WIDE
BENCHMARK(run<lanes_bench::bicycle_kane_float_x16, bicycles>)
    ->Name(KANE_LANES_GROUP "/bicycle/kane_float_x16");
#endif

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
