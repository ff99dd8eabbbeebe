// A floating base on Euler parameters with body rates carrying two one-link arms (floating_arms.hpp,
// 8 speeds, Kane's sums): kane::linearize against central differences of kane::motion (1e-7
// relative) and against jets of one direction carried through kane::motion, M on jets (1e-10);
// kane::inverse_dynamics (f with the state's u', M not formed) against M u' - f.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include <kane/kane.hpp>

#include "differences.hpp"
#include "floating_arms.hpp"

namespace {
namespace fa = floating_arms;
constexpr std::size_t nq = fa::state::nq, nu = fa::state::nu, nx = nq + nu, nr = fa::state::nr;
using vector_x = Eigen::Matrix<double, int(nx), 1>;

fa::state sample(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  fa::state s;
  for (auto& x : s.q) x = d(rng);
  for (auto& x : s.u) x = d(rng);
  const double norm = std::sqrt(s.q[0] * s.q[0] + s.q[1] * s.q[1] + s.q[2] * s.q[2] + s.q[3] * s.q[3]);
  for (std::size_t i = 0; i < 4; ++i) s.q[i] /= norm;
  s.r = {70.0, 0.4, -0.3};
  return s;
}
// x' of kane::motion at x and the inputs r
vector_x rates(const fa::state& s, const std::array<double, nx>& x, const std::array<double, nr>& r) {
  kane::motion<fa::system, fa::speeds> rhs(s);
  rhs.inputs() = r;
  std::array<double, nx> dx{};
  rhs(x, dx, s.t);
  REQUIRE(rhs.status() == kane::solve_status::ok);
  return Eigen::Map<const vector_x>(dx.data());
}
}  // namespace

TEST_CASE("linearize: a floating base with two arms against central differences and jets", "[linearize]") {
  const fa::state s = sample(5);
  const auto lin = kane::linearize<fa::system, fa::evaluator, fa::inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  std::array<double, nx> x{};
  for (std::size_t i = 0; i < nq; ++i) x[i] = s.q[i];
  for (std::size_t i = 0; i < nu; ++i) x[nq + i] = s.u[i];
  CHECK(relative(lin.rate, rates(s, x, s.r)) < 1e-12);

  Eigen::Matrix<double, int(nx), int(nx + nr)> diff;
  const double h = 1e-6;
  for (std::size_t j = 0; j < nx + nr; ++j) {
    std::array<double, nx> xp = x, xm = x;
    std::array<double, nr> rp = s.r, rm = s.r;
    (j < nx ? xp[j] : rp[j - nx]) += h;
    (j < nx ? xm[j] : rm[j - nx]) -= h;
    diff.col(Eigen::Index(j)) = (rates(s, xp, rp) - rates(s, xm, rm)) / (2 * h);
  }
  CHECK(relative(lin.A, diff.leftCols<int(nx)>()) < 1e-7);
  CHECK(relative(lin.B, diff.rightCols<int(nr)>()) < 1e-7);

  // one direction d of (x, r) on jets through kane::motion: u' = M^-1 f with M and f on jets
  using J = kane::jet<double, 1>;
  using jet_evaluator = kane::system_evaluator<fa::system, fa::speeds, kane::level::acceleration,
                                               kane::state_of<fa::system, fa::speeds, J>>;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (int k = 0; k < 3; ++k) {
    Eigen::Matrix<double, int(nx + nr), 1> dir;
    for (auto& v : dir) v = d(rng);
    auto js = kane::detail::lift<1>(s);
    std::array<J, nx> jx, jdx;
    for (std::size_t i = 0; i < nx; ++i) jx[i] = x[i] + J::variable(0.0, 0) * dir(Eigen::Index(i));
    kane::motion<fa::system, jet_evaluator> rhs(js);
    for (std::size_t i = 0; i < nr; ++i)
      rhs.inputs()[i] = s.r[i] + J::variable(0.0, 0) * dir(Eigen::Index(nx + i));
    rhs(jx, jdx, js.t);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    vector_x along;
    for (std::size_t i = 0; i < nx; ++i) along(Eigen::Index(i)) = jdx[i].part(0);
    CHECK(relative(vector_x(lin.A * dir.head<int(nx)>() + lin.B * dir.tail<int(nr)>()), along) < 1e-10);
  }
}

TEST_CASE("inverse dynamics on Kane's sums: tau = M u' - f, zero at u' = M^-1 f", "[dynamics]") {
  fa::state s = sample(11);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  for (auto& x : s.ud) x = d(rng);
  fa::evaluator ev;
  ev.update(s);
  const auto e = kane::mass_matrix_and_forcing<fa::system>(ev);
  Eigen::Matrix<double, int(nu), 1> ud;
  for (std::size_t i = 0; i < nu; ++i) ud(Eigen::Index(i)) = s.ud[i];
  const auto [tau, status] = kane::inverse_dynamics<fa::system>(ev);
  REQUIRE(status == kane::solve_status::ok);
  CHECK(relative(tau, e.M * ud - e.f) < 1e-12);
  CHECK(relative(kane::forcing<fa::system>(ev).f, e.f) < 1e-12);

  const auto [solved, ok] = kane::forward_dynamics<fa::system>(ev);
  REQUIRE(ok == kane::solve_status::ok);
  for (std::size_t i = 0; i < nu; ++i) s.ud[i] = solved(Eigen::Index(i));
  ev.update(s);
  CHECK(kane::inverse_dynamics<fa::system>(ev).tau.cwiseAbs().maxCoeff() <
        1e-10 * (1 + e.f.cwiseAbs().maxCoeff()));
}
