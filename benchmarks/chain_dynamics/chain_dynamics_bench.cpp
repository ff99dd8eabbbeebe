// Forward dynamics of the n-link chain (chain_dynamics.hpp), n = 6, 12, 24, 48:
// kane beside Orocos KDL's ChainDynParam + LLT and a hand-written
// articulated-body algorithm (O(n)); kane's code of each n is its own translation unit.
// Its derivatives by q and q': kane's analytical ones beside central differences of kane's
// forward dynamics (4n calls), the ratio users compare with; kane's inverse dynamics at a random q''
// and its analytical derivatives.
#include <algorithm>
#include <array>
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
// the derivatives of the values M of F's output by q and q' (column-major N x N), by central
// differences of F: 4N calls
template <std::size_t N, auto F, auto M>
void central_of(const input& in, double* dq, double* du) {
  const double h = 1e-6;
  decltype(bench::output_of(F)) a, b;
  input x = in;
  const auto column = [&](std::array<double, max_n>& v, std::size_t j, double* out) {
    const double v0 = v[j];
    v[j] = v0 + h, F(x, a);
    v[j] = v0 - h, F(x, b);
    v[j] = v0;
    for (std::size_t i = 0; i < N; ++i) out[j * N + i] = ((a.*M)[i] - (b.*M)[i]) / (2 * h);
  };
  for (std::size_t j = 0; j < N; ++j) column(x.q, j, dq), column(x.qd, j, du);
}
// du'/dq and du'/du by central differences of kane_forward<N>
template <std::size_t N>
void central(const input& in, derivatives& out) {
  central_of<N, kane_forward<N>, &output::qdd>(in, out.dq, out.du);
}
// two N x N matrices agree to 1e-6 of the largest entry of y (at least 1), else the bench stops
template <std::size_t N>
void require_close(const double* x, const double* y, const char* what) {
  double scale = 1;
  for (std::size_t k = 0; k < N * N; ++k) scale = std::fmax(scale, std::fabs(y[k]));
  if (!(bench::max_diff(x, y, int(N * N)) / scale < 1e-6)) {
    std::fprintf(stderr, "chain_dynamics/%zu: %s and central differences disagree\n", N, what);
    std::exit(1);
  }
}
// the analytical derivatives agree with the differences
template <std::size_t N>
void derivatives_agree(const input& in, const output& h) {
  static derivatives d, c;
  kane_derivatives<N>(in, d);
  central<N>(in, c);
  require_close<N>(d.dq, c.dq, "derivatives by q"), require_close<N>(d.du, c.du, "derivatives by q'");
  output u{};
  std::copy(d.ud, d.ud + N, u.qdd);
  bench::require_agreement(difference<N>(u, h));
}
// tau at q'' = the hand ABA's is 0 (no joint torques), and the inverse derivatives agree with central
// differences of kane_inverse
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
  central_of<N, kane_inverse<N>, &torques::tau>(in, cq, cu);
  require_close<N>(d.dq, cq, "inverse derivatives by q"),
      require_close<N>(d.du, cu, "inverse derivatives by q'");
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
