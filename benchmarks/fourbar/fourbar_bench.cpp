// kane beside the hand-written four-bar: a loop closed from a guess 0.1 rad of crank away.
#include <cmath>
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "fourbar.hpp"

namespace {
std::vector<fourbar::input> inputs() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(0, 2 * M_PI);
  std::vector<fourbar::input> in(64);
  const double a = 0.3, b = 1.0, c = 0.8, g = 1.1;
  for (auto& x : in) {
    const double q1 = d(rng), guess = q1 - 0.1;  // the closed loop at the guess's crank angle
    const double px = a * std::cos(guess), py = a * std::sin(guess), ex = g - px, ey = -py,
                 e = std::hypot(ex, ey);
    const double q2 = std::atan2(ey, ex) + std::acos((b * b + e * e - c * c) / (2 * b * e));
    const double q3 = std::atan2(py + b * std::sin(q2), px + b * std::cos(q2) - g);
    x.q = {q1, q2, q3};
    x.p = {a, b, c, g};
  }
  return in;
}
const std::vector<fourbar::input> states = inputs();

void agree() {
  for (const auto& in : states) {
    fourbar::output k{}, h{};
    fourbar::kane_solve(in, k);
    fourbar::hand_solve(in, h);
    bench::require_agreement(std::fmax(bench::max_diff(k.q, h.q, 2), bench::max_diff(k.A, h.A, 2)));
  }
}
}  // namespace

BENCHMARK(bench::run<fourbar::hand_solve, states>)->Name("fourbar/close_loop_and_A/hand");
BENCHMARK(bench::run<fourbar::kane_solve, states>)->Name("fourbar/close_loop_and_A/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
