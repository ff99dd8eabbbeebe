// The Whipple bicycle: kane (constrained_motion, linearize_constrained) beside SymPy's
// generated C (bicycle_sympy.cpp, tests/data/gen_bicycle_sympy.py). Before anything is timed, at 64
// random non-upright states: x' agrees (|x'_k - x'_s| <= 1e-10 max|x'_s|), A agrees
// (|A_k - A_s| <= 1e-9 max|A_s|), and at 16 of them kane's A agrees with central differences
// of SymPy's x' (the pitch closed again at each perturbed state) to 1e-6.
#include <cstdio>
#include <random>
#include <vector>

#include "../../examples/models/bicycle.hpp"
#include "../common/harness.hpp"
#include "bicycle.hpp"

namespace {
namespace b = models::bicycle;
std::array<double, 27> benchmark_p() {
  std::array<double, 27> out{};
  const b::dynamics_state s = b::benchmark_parameters();
  for (std::size_t i = 0; i < 27; ++i) out[i] = s.p[i];
  return out;
}
}  // namespace

const std::array<double, 27> bicycle::p = benchmark_p();

namespace {
// q1, q2 in [-2, 2], yaw in [-pi, pi], roll and steer in [-0.5, 0.5], the pitch closing the
// holonomic constraint (kane::solve_configuration), u4, u6 in [-1, 1] rad/s, u7 = v / rR
// with v in [2, 8] m/s (forward).
std::vector<bicycle::input> inputs() {
  std::mt19937 rng(2007);
  std::uniform_real_distribution<double> xy(-2, 2), yaw(-M_PI, M_PI), angle(-0.5, 0.5), rate(-1, 1), v(2, 8);
  std::vector<bicycle::input> in(64);
  for (auto& x : in) {
    b::dynamics_state s = b::benchmark_parameters();
    s.q = {xy(rng), xy(rng), yaw(rng), angle(rng), 0.0, angle(rng)};
    b::dynamics_evaluator ev;
    if (kane::solve_configuration<b::pitch>(ev, s).status != kane::solve_status::ok) {
      std::fprintf(stderr, "the pitch did not close\n");
      std::exit(1);
    }
    for (std::size_t i = 0; i < 6; ++i) x.x[i] = s.q[i];
    x.x[6] = rate(rng), x.x[7] = rate(rng), x.x[8] = v(rng) / s.p[1];
  }
  return in;
}
const std::vector<bicycle::input> states = inputs();

double relative(const double* a, const double* b, int n) {
  double scale = 0;
  for (int i = 0; i < n; ++i) scale = std::fmax(scale, std::fabs(b[i]));
  return bench::max_diff(a, b, n) / scale;
}

// SymPy's x' at x_ind = (q1, q2, q3, q4, q6, u4, u6, u7) with the pitch closed (kane's Newton
// on the holonomic constraint, started from the pitch of the state near which it is called).
void sympy_rates_ind(const double* xi, double q5, double* out) {
  b::dynamics_state s = b::benchmark_parameters();
  s.q = {xi[0], xi[1], xi[2], xi[3], q5, xi[4]};
  b::dynamics_evaluator ev;
  if (kane::solve_configuration<b::pitch>(ev, s).status != kane::solve_status::ok) std::exit(1);
  bicycle::input in;
  in.x = {s.q[0], s.q[1], s.q[2], s.q[3], s.q[4], s.q[5], xi[5], xi[6], xi[7]};
  bicycle::rates r{};
  bicycle::sympy_rates(in, r);
  const int rows[8] = {0, 1, 2, 3, 5, 6, 7, 8};  // drop q5'
  for (int i = 0; i < 8; ++i) out[i] = r.xd[rows[i]];
}

// max |A_kane - A_fd| / max |A_fd| over 16 random states, A_fd by central differences.
double differences() {
  double worst = 0;
  for (std::size_t n = 0; n < 16; ++n) {
    const auto& in = states[n];
    const double x[8] = {in.x[0], in.x[1], in.x[2], in.x[3], in.x[5], in.x[6], in.x[7], in.x[8]};
    double fd[64];
    for (int j = 0; j < 8; ++j) {
      const double h = 1e-5 * std::fmax(1, std::fabs(x[j]));
      double xp[8], xm[8], fp[8], fm[8];
      for (int i = 0; i < 8; ++i) xp[i] = xm[i] = x[i];
      xp[j] += h, xm[j] -= h;
      sympy_rates_ind(xp, in.x[4], fp);
      sympy_rates_ind(xm, in.x[4], fm);
      for (int i = 0; i < 8; ++i) fd[8 * i + j] = (fp[i] - fm[i]) / (2 * h);
    }
    bicycle::linear k{};
    bicycle::kane_A(in, k);
    worst = std::fmax(worst, relative(k.A, fd, 64));
  }
  return worst;
}

void agree() {
  double worst_rates = 0, worst_A = 0;
  for (const auto& in : states) {
    bicycle::rates k{}, s{};
    bicycle::kane_rates(in, k);
    bicycle::sympy_rates(in, s);
    worst_rates = std::fmax(worst_rates, relative(k.xd, s.xd, 9));
  }
  for (const auto& in : states) {
    bicycle::linear k{}, s{};
    bicycle::kane_A(in, k);
    bicycle::sympy_A(in, s);
    worst_A = std::fmax(worst_A, relative(k.A, s.A, 64));
  }
  const double worst_fd = differences();
  std::fprintf(stderr,
               "kane and SymPy at %zu random states: x' %.1e, A %.1e; kane's A against central differences "
               "of SymPy's x' at 16 of them %.1e (relative)\n",
               states.size(), worst_rates, worst_A, worst_fd);
  if (!(worst_rates <= 1e-10) || !(worst_A <= 1e-9) || !(worst_fd <= 1e-6)) {
    std::fprintf(stderr,
                 "implementations disagree (beyond 1e-10 for x', 1e-9 for A, 1e-6 for differences)\n");
    std::exit(1);
  }
}
}  // namespace

BENCHMARK(bench::run<bicycle::sympy_rates, states>)->Name("bicycle/u_dot/sympy");
BENCHMARK(bench::run<bicycle::kane_rates, states>)->Name("bicycle/u_dot/kane");
BENCHMARK(bench::run<bicycle::sympy_A, states>)->Name("bicycle/A/sympy");
BENCHMARK(bench::run<bicycle::kane_A, states>)->Name("bicycle/A/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
