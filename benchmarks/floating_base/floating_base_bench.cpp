// The floating base with two eight-link arms (22 speeds): forward dynamics, its analytical
// derivatives beside central differences, and kane::linearize by the derivatives beside jets
// through the whole evaluator.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "../common/harness.hpp"
#include "floating_base.hpp"

namespace {
using floating_base::nq;
using floating_base::nu;
std::vector<floating_base::input> inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<floating_base::input> in(64);
  for (auto& x : in) {
    for (auto& v : x.q) v = d(rng);
    for (auto& v : x.u) v = d(rng);
    const double norm = std::sqrt(x.q[0] * x.q[0] + x.q[1] * x.q[1] + x.q[2] * x.q[2] + x.q[3] * x.q[3]);
    for (int i = 0; i < 4; ++i) x.q[i] /= norm;
  }
  return in;
}
const std::vector<floating_base::input> states = inputs();

bool close(const double* x, const double* y, std::size_t n, double tolerance) {
  double scale = 1;
  for (std::size_t k = 0; k < n; ++k) scale = std::fmax(scale, std::fabs(y[k]));
  return bench::max_diff(x, y, int(n)) / scale < tolerance;
}
// u's rows of A along the motion of each speed: the Euler parameters' columns times G(e)
void along_speeds(const floating_base::input& in, const double* a, double* dq) {
  const double e0 = in.q[0], e1 = in.q[1], e2 = in.q[2], e3 = in.q[3];
  const double g[4][3] = {{-e1, -e2, -e3}, {e0, -e3, e2}, {e3, e0, -e1}, {-e2, e1, e0}};
  for (std::size_t i = 0; i < nu; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      dq[j * nu + i] = 0;
      for (std::size_t k = 0; k < 4; ++k) dq[j * nu + i] += 0.5 * a[k * nu + i] * g[k][j];
    }
    for (std::size_t j = 3; j < nu; ++j) dq[j * nu + i] = a[(j + 1) * nu + i];
  }
}

void agree() {
  for (const auto& in : states) {
    floating_base::output f{}, d{}, c{}, l{}, j{}, t{};
    floating_base::kane_forward(in, f);
    floating_base::kane_derivatives(in, d);
    floating_base::central(in, c);
    floating_base::kane_linearize(in, l);
    floating_base::jets_linearize(in, j);
    floating_base::kane_linearize_tangent(in, t);
    if (f.status || d.status || c.status || l.status || j.status || t.status) {
      std::fprintf(stderr, "floating_base: a status is not ok\n");
      std::exit(1);
    }
    // u' by forward dynamics and by the derivatives' own factor of M: equal to rounding, relative to |u'|
    if (!close(d.ud, f.ud, nu, 1e-12) || !close(l.ud, f.ud, nu, 1e-12)) {
      std::fprintf(stderr, "floating_base: u' of forward dynamics and of the derivatives disagree\n");
      std::exit(1);
    }
    double lq[nu * nu], jq[nu * nu];
    along_speeds(in, l.a, lq), along_speeds(in, j.a, jq);
    const bool derivatives = close(d.dq, c.dq, nu * nu, 1e-6) && close(d.du, c.du, nu * nu, 1e-6),
               linearized = close(lq, jq, nu * nu, 1e-9) && close(lq, d.dq, nu * nu, 1e-9) &&
                            close(l.a + nu * nq, j.a + nu * nq, nu * nu, 1e-9) &&
                            close(f.ud, j.ud, nu, 1e-12);
    if (!derivatives || !linearized) {
      std::fprintf(stderr, "floating_base: the derivatives, central differences and jets disagree\n");
      std::exit(1);
    }
  }
}
}  // namespace

BENCHMARK(bench::run<floating_base::kane_forward, states>)->Name("floating_base/forward/kane");
BENCHMARK(bench::run<floating_base::kane_derivatives, states>)->Name("floating_base/derivatives/kane");
BENCHMARK(bench::run<floating_base::central, states>)->Name("floating_base/central/kane");
BENCHMARK(bench::run<floating_base::kane_linearize, states>)->Name("floating_base/linearize/kane");
BENCHMARK(bench::run<floating_base::jets_linearize, states>)->Name("floating_base/linearize_jets/kane");
BENCHMARK(bench::run<floating_base::kane_linearize_tangent, states>)
    ->Name("floating_base/linearize_tangent/kane");

int main(int argc, char** argv) { return bench::main(argc, argv, agree); }
