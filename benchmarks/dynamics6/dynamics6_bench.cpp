// Forward and inverse dynamics of the 6-revolute chain with link masses: kane beside a
// hand-written CRBA + RNEA + LLT (RNEA for tau) and Orocos KDL's ChainDynParam + LLT
// (ChainIdSolver_RNE for tau).
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "dynamics6.hpp"

namespace {
std::vector<dynamics6::input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<dynamics6::input> in(64);
  for (auto& x : in)
    for (int i = 0; i < 6; ++i) x.q[i] = d(rng), x.qd[i] = d(rng);
  for (auto& x : in)  // after q and q', which stay the states they were
    for (int i = 0; i < 6; ++i) x.qdd_in[i] = d(rng);
  return in;
}
const std::vector<dynamics6::input> states = inputs();

// d tau (or d q'') by q and q' by central differences of f: 24 calls
void central(void (*f)(const dynamics6::input&, dynamics6::output&), const dynamics6::input& in,
             dynamics6::output& out) {
  const double h = 1e-6;
  dynamics6::output a{}, b{};
  dynamics6::input x = in;
  const bool forward = f == dynamics6::kane_forward;
  const auto column = [&](double* d, int j) {
    for (int i = 0; i < 6; ++i)
      d[6 * j + i] = forward ? (a.qdd[i] - b.qdd[i]) / (2 * h) : (a.tau[i] - b.tau[i]) / (2 * h);
  };
  for (int j = 0; j < 6; ++j) {
    x.q[j] = in.q[j] + h, f(x, a), x.q[j] = in.q[j] - h, f(x, b), x.q[j] = in.q[j], column(out.dq, j);
    x.qd[j] = in.qd[j] + h, f(x, a), x.qd[j] = in.qd[j] - h, f(x, b), x.qd[j] = in.qd[j], column(out.du, j);
  }
}
void central_forward(const dynamics6::input& in, dynamics6::output& out) {
  central(dynamics6::kane_forward, in, out);
}
bool close(const double* x, const double* y) {
  double scale = 1;
  for (int k = 0; k < 36; ++k) scale = std::fmax(scale, std::fabs(y[k]));
  return bench::max_diff(x, y, 36) / scale < 1e-6;
}

void agree() {
  for (const auto& in : states) {
    dynamics6::output k{}, h{}, o{}, kb{};
    dynamics6::kane_forward(in, k);  // q'' alone
    dynamics6::kane_bias(in, kb);    // M and h
    dynamics6::hand_forward(in, h);
    dynamics6::kdl_forward(in, o);
    bench::require_agreement(std::fmax(bench::max_diff(kb.M, h.M, 42), bench::max_diff(o.M, h.M, 48)));
    bench::require_agreement(bench::max_diff(k.qdd, h.qdd, 6));
    dynamics6::output m{};  // kane's M alone (a pose-level evaluator)
    dynamics6::kane_mass(in, m);
    bench::require_agreement(bench::max_diff(m.M, h.M, 36));
    dynamics6::output kt{}, ht{}, ot{};  // tau alone, and tau = M q''_in + h from hand's M and h
    dynamics6::kane_inverse(in, kt);
    dynamics6::hand_inverse(in, ht);
    dynamics6::kdl_inverse(in, ot);
    double tau[6];
    for (int i = 0; i < 6; ++i) {
      tau[i] = h.h[i];
      for (int j = 0; j < 6; ++j) tau[i] += h.M[6 * j + i] * in.qdd_in[j];
    }
    bench::require_agreement(
        std::fmax(bench::max_diff(kt.tau, ht.tau, 6), bench::max_diff(ot.tau, ht.tau, 6)));
    bench::require_agreement(bench::max_diff(tau, ht.tau, 6));
    // the derivatives against central differences of kane's tau and q'' (1e-6 of the largest entry)
    dynamics6::output di{}, df{}, ci{}, cf{};
    dynamics6::kane_inverse_derivatives(in, di);
    dynamics6::kane_forward_derivatives(in, df);
    central(dynamics6::kane_inverse, in, ci);
    central(dynamics6::kane_forward, in, cf);
    bench::require_agreement(
        std::fmax(bench::max_diff(di.tau, kt.tau, 6), bench::max_diff(df.qdd, k.qdd, 6)));
    if (!(close(di.dq, ci.dq) && close(di.du, ci.du) && close(df.dq, cf.dq) && close(df.du, cf.du))) {
      std::fprintf(stderr, "dynamics6: derivatives and central differences disagree\n");
      std::exit(1);
    }
  }
}
}  // namespace

BENCHMARK(bench::run<dynamics6::hand_mass, states>)->Name("dynamics6/M/hand");
BENCHMARK(bench::run<dynamics6::kane_mass, states>)->Name("dynamics6/M/kane");
BENCHMARK(bench::run<dynamics6::kdl_mass, states>)->Name("dynamics6/M/kdl");
BENCHMARK(bench::run<dynamics6::hand_bias, states>)->Name("dynamics6/M_and_bias/hand");
BENCHMARK(bench::run<dynamics6::kane_bias, states>)->Name("dynamics6/M_and_bias/kane");
BENCHMARK(bench::run<dynamics6::kdl_bias, states>)->Name("dynamics6/M_and_bias/kdl");
BENCHMARK(bench::run<dynamics6::hand_forward, states>)->Name("dynamics6/forward/hand");
BENCHMARK(bench::run<dynamics6::kane_forward, states>)->Name("dynamics6/forward/kane");
BENCHMARK(bench::run<dynamics6::kdl_forward, states>)->Name("dynamics6/forward/kdl");
BENCHMARK(bench::run<dynamics6::hand_inverse, states>)->Name("dynamics6/inverse/hand");
BENCHMARK(bench::run<dynamics6::kane_inverse, states>)->Name("dynamics6/inverse/kane");
BENCHMARK(bench::run<dynamics6::kdl_inverse, states>)->Name("dynamics6/inverse/kdl");
BENCHMARK(bench::run<dynamics6::kane_inverse_derivatives, states>)
    ->Name("dynamics6/inverse_derivatives/kane");
BENCHMARK(bench::run<dynamics6::kane_forward_derivatives, states>)
    ->Name("dynamics6/forward_derivatives/kane");
BENCHMARK(bench::run<central_forward, states>)->Name("dynamics6/forward_central/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
