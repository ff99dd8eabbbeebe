// kane beside the hand-written outward pass and KDL for the 6-revolute chain: kane with a local
// evaluator in every call (kane) and with evaluators kept across calls, as a controller keeps them
// (kane_kept).
#include <random>
#include <vector>

#include "../common/harness.hpp"
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

double diff(const arm6::output& a, const arm6::output& b) {
  return bench::max_diff(a.R, b.R, sizeof(arm6::output) / sizeof(double));
}

void agree() {
  for (const auto& in : states) {
    arm6::output k{}, h{}, o{}, kk{};
    arm6::kane_all(in, k);
    arm6::hand_all(in, h);
    arm6::kdl_all(in, o);
    arm6::kane_kept_all(in, kk);
    double d = std::fmax(std::fmax(diff(k, h), diff(o, h)), diff(kk, h));
    using F = void (*)(const arm6::input&, arm6::output&);
    const F kq[] = {arm6::kane_q1, arm6::kane_q2, arm6::kane_q3, arm6::kane_q4},
            kept[] = {arm6::kane_kept_q1, arm6::kane_kept_q2, arm6::kane_kept_q3, arm6::kane_kept_q4},
            hq[] = {arm6::hand_q1, arm6::hand_q2, arm6::hand_q3, arm6::hand_q4};
    for (int i = 0; i < 4; ++i)
      for (const F f : {kq[i], kept[i]}) {
        arm6::output kk{}, hh{};
        f(in, kk);
        hq[i](in, hh);
        // Q1 compares every field (the others are zero on both sides), Q2 .. Q4 those from w on.
        kk.R[0] = hh.R[0] = 0;
        d = std::fmax(d, i == 0 ? diff(kk, hh) : bench::max_diff(kk.w, hh.w, 48));
      }
    bench::require_agreement(d);
  }
}
}  // namespace

BENCHMARK(bench::run<arm6::hand_q1, states>)->Name("arm6/Q1_pose/hand");
BENCHMARK(bench::run<arm6::kane_q1, states>)->Name("arm6/Q1_pose/kane");
BENCHMARK(bench::run<arm6::kane_kept_q1, states>)->Name("arm6/Q1_pose/kane_kept");
BENCHMARK(bench::run<arm6::hand_q2, states>)->Name("arm6/Q2_velocity/hand");
BENCHMARK(bench::run<arm6::kane_q2, states>)->Name("arm6/Q2_velocity/kane");
BENCHMARK(bench::run<arm6::kane_kept_q2, states>)->Name("arm6/Q2_velocity/kane_kept");
BENCHMARK(bench::run<arm6::hand_q3, states>)->Name("arm6/Q3_jacobian/hand");
BENCHMARK(bench::run<arm6::kane_q3, states>)->Name("arm6/Q3_jacobian/kane");
BENCHMARK(bench::run<arm6::kane_kept_q3, states>)->Name("arm6/Q3_jacobian/kane_kept");
BENCHMARK(bench::run<arm6::hand_q4, states>)->Name("arm6/Q4_acceleration/hand");
BENCHMARK(bench::run<arm6::kane_q4, states>)->Name("arm6/Q4_acceleration/kane");
BENCHMARK(bench::run<arm6::kane_kept_q4, states>)->Name("arm6/Q4_acceleration/kane_kept");
BENCHMARK(bench::run<arm6::hand_all, states>)->Name("arm6/ALL/hand");
BENCHMARK(bench::run<arm6::kane_all, states>)->Name("arm6/ALL/kane");
BENCHMARK(bench::run<arm6::kane_kept_all, states>)->Name("arm6/ALL/kane_kept");
BENCHMARK(bench::run<arm6::kdl_q1, states>)->Name("arm6/Q1_pose/kdl");
BENCHMARK(bench::run<arm6::kdl_q2, states>)->Name("arm6/Q2_velocity/kdl");
BENCHMARK(bench::run<arm6::kdl_q3, states>)->Name("arm6/Q3_jacobian/kdl");
BENCHMARK(bench::run<arm6::kdl_q4, states>)->Name("arm6/Q4_acceleration/kdl");
BENCHMARK(bench::run<arm6::kdl_all, states>)->Name("arm6/ALL/kdl");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
