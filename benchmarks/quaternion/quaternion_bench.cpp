// kane beside the hand-written free body: q' of Euler parameters and a point's velocity.
#include <cmath>
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "quaternion.hpp"

namespace {
std::vector<quaternion::input> inputs() {
  std::mt19937 rng(13);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> d(-2, 2);
  std::vector<quaternion::input> in(64);
  for (auto& x : in) {
    double n = 0;
    for (int i = 0; i < 4; ++i) x.q[i] = g(rng), n += x.q[i] * x.q[i];
    for (int i = 0; i < 4; ++i) x.q[i] /= std::sqrt(n);
    for (int i = 4; i < 7; ++i) x.q[i] = d(rng);
    for (auto& u : x.u) u = d(rng);
    for (auto& p : x.p) p = d(rng) / 2;
  }
  return in;
}
const std::vector<quaternion::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    quaternion::output k{}, h{};
    quaternion::kane_rates(in, k);
    quaternion::hand_rates(in, h);
    bench::require_agreement(std::fmax(bench::max_diff(k.qd, h.qd, 7), bench::max_diff(k.v, h.v, 3)));
  }
}
}  // namespace

BENCHMARK(bench::run<quaternion::hand_rates, states>)->Name("quaternion/qdot_and_v/hand");
BENCHMARK(bench::run<quaternion::kane_rates, states>)->Name("quaternion/qdot_and_v/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
