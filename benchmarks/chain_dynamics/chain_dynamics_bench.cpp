// Forward dynamics of the n-link chain (chain_dynamics.hpp), n = 6, 12, 24, 48:
// kane beside Orocos KDL's ChainDynParam + LLT and a hand-written
// articulated-body algorithm (O(n)); kane's code of each n is its own translation unit.
// Its derivatives by q and q': kane's analytical ones beside central differences of kane's
// forward dynamics (4n calls), the ratio users compare with; kane's inverse dynamics at a random q''
// and its analytical derivatives.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "../common/harness.hpp"
#include "chain_dynamics.hpp"

namespace {
using namespace chain_dynamics;
template <std::size_t... N>
struct sizes {};
using all = sizes<6, 12, 24, 48>;

std::vector<input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-3, 3);
  std::vector<input> in(64);
  for (auto& x : in)
    for (std::size_t i = 0; i < max_n; ++i) x.q[i] = d(rng), x.qd[i] = d(rng), x.qdd[i] = d(rng);
  return in;
}
const std::vector<input> states = inputs();

// |a - h| / max(1, |h|), over (n / 6)^2: M's condition grows with n (ABA and KDL's
// LLT differ by up to 7e-15 max(1, |q''|) at n = 6, 2.4e-12 at n = 48)
template <std::size_t N>
double difference(const output& a, const output& h) {
  const double scale = std::fmax(1, std::fabs(*std::max_element(h.qdd, h.qdd + N, [](double x, double y) {
                                   return std::fabs(x) < std::fabs(y);
                                 })));
  return bench::max_diff(a.qdd, h.qdd, N) / scale / ((N / 6.0) * (N / 6.0));
}
// du'/dq and du'/du by central differences of kane_forward<N>: 4N calls
template <std::size_t N>
void central(const input& in, derivatives& out) {
  const double h = 1e-6;
  output a, b;
  input x = in;
  for (std::size_t j = 0; j < N; ++j) {
    x.q[j] = in.q[j] + h, kane_forward<N>(x, a);
    x.q[j] = in.q[j] - h, kane_forward<N>(x, b);
    x.q[j] = in.q[j];
    for (std::size_t i = 0; i < N; ++i) out.dq[j * N + i] = (a.qdd[i] - b.qdd[i]) / (2 * h);
    x.qd[j] = in.qd[j] + h, kane_forward<N>(x, a);
    x.qd[j] = in.qd[j] - h, kane_forward<N>(x, b);
    x.qd[j] = in.qd[j];
    for (std::size_t i = 0; i < N; ++i) out.du[j * N + i] = (a.qdd[i] - b.qdd[i]) / (2 * h);
  }
}
// the analytical derivatives and the differences agree to 1e-6 of the largest entry
template <std::size_t N>
void derivatives_agree(const input& in, const output& h) {
  static derivatives d, c;
  kane_derivatives<N>(in, d);
  central<N>(in, c);
  const auto close = [](const double* x, const double* y) {
    double scale = 1;
    for (std::size_t k = 0; k < N * N; ++k) scale = std::fmax(scale, std::fabs(y[k]));
    return bench::max_diff(x, y, int(N * N)) / scale;
  };
  if (!(close(d.dq, c.dq) < 1e-6 && close(d.du, c.du) < 1e-6)) {
    std::fprintf(stderr, "chain_dynamics/%zu: derivatives and central differences disagree\n", N);
    std::exit(1);
  }
  output u{};
  std::copy(d.ud, d.ud + N, u.qdd);
  bench::require_agreement(difference<N>(u, h));
}
// tau at q'' = the hand ABA's is 0 (no joint torques), and the inverse derivatives agree with central
// differences of kane_inverse to 1e-6 of the largest entry
template <std::size_t N>
void inverse_agrees(const input& in, const output& h) {
  input at = in;
  std::copy(h.qdd, h.qdd + N, at.qdd.begin());
  torques t{};
  kane_inverse<N>(at, t);
  double scale = 1;
  for (std::size_t k = 0; k < N; ++k) scale = std::fmax(scale, std::fabs(h.qdd[k]));
  const double zero[max_n] = {};
  bench::require_agreement(bench::max_diff(t.tau, zero, int(N)) / scale / ((N / 6.0) * (N / 6.0)));
  static inverse_derivatives d;
  static double cq[max_n * max_n], cu[max_n * max_n];
  kane_inverse_derivatives<N>(in, d);
  const double e = 1e-6;
  for (std::size_t j = 0; j < N; ++j) {
    torques a{}, b{};
    input x = in;
    x.q[j] = in.q[j] + e, kane_inverse<N>(x, a), x.q[j] = in.q[j] - e, kane_inverse<N>(x, b),
    x.q[j] = in.q[j];
    for (std::size_t i = 0; i < N; ++i) cq[j * N + i] = (a.tau[i] - b.tau[i]) / (2 * e);
    x.qd[j] = in.qd[j] + e, kane_inverse<N>(x, a), x.qd[j] = in.qd[j] - e, kane_inverse<N>(x, b);
    for (std::size_t i = 0; i < N; ++i) cu[j * N + i] = (a.tau[i] - b.tau[i]) / (2 * e);
  }
  const auto close = [](const double* x, const double* y) {
    double s = 1;
    for (std::size_t k = 0; k < N * N; ++k) s = std::fmax(s, std::fabs(y[k]));
    return bench::max_diff(x, y, int(N * N)) / s;
  };
  if (!(close(d.dq, cq) < 1e-6 && close(d.du, cu) < 1e-6)) {
    std::fprintf(stderr, "chain_dynamics/%zu: inverse derivatives and central differences disagree\n", N);
    std::exit(1);
  }
}
template <std::size_t N>
void agree_at() {
  for (const auto& in : states) {
    output h{}, k{}, o{};
    hand_forward<N>(in, h);
    kdl_forward<N>(in, o);
    kane_forward<N>(in, k);
    bench::require_agreement(std::fmax(difference<N>(o, h), difference<N>(k, h)));
  }
  for (std::size_t i = 0; i < 4; ++i) {
    output h{};
    hand_forward<N>(states[i], h);
    derivatives_agree<N>(states[i], h);
    inverse_agrees<N>(states[i], h);
  }
}
template <std::size_t... N>
void agree(sizes<N...>) {
  (agree_at<N>(), ...);
}

template <std::size_t N>
void rows() {
  const std::string n = "chain_dynamics/" + std::to_string(N);
  benchmark::RegisterBenchmark((n + "/hand").c_str(), bench::run<hand_forward<N>, states>);
  benchmark::RegisterBenchmark((n + "/kane").c_str(), bench::run<kane_forward<N>, states>);
  benchmark::RegisterBenchmark((n + "/kdl").c_str(), bench::run<kdl_forward<N>, states>);
  benchmark::RegisterBenchmark((n + "/derivatives/kane").c_str(), bench::run<kane_derivatives<N>, states>);
  benchmark::RegisterBenchmark((n + "/central/kane").c_str(), bench::run<central<N>, states>);
  benchmark::RegisterBenchmark((n + "/inverse/kane").c_str(), bench::run<kane_inverse<N>, states>);
  benchmark::RegisterBenchmark((n + "/inverse_derivatives/kane").c_str(),
                               bench::run<kane_inverse_derivatives<N>, states>);
}
template <std::size_t... N>
bool register_rows(sizes<N...>) {
  (rows<N>(), ...);
  return true;
}
const bool registered = register_rows(all{});
}  // namespace

int main(int argc, char** argv) {
  return bench::main(argc, argv, [] { agree(all{}); });
}
