// kane::eigenvalues against closed forms, the eigenvalues of Meijaard et al. (2007) from the
// paper's own M, C1, K0 and K2 (tests/data/meijaard2007.hpp), and Eigen's EigenSolver
// (eigenvalues.cpp) on random matrices; its statuses on bad input.
#include <Eigen/LU>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include "data/meijaard2007.hpp"
#include "eigenvalues.hpp"
#include "kane/linearization/eigenvalues.hpp"

namespace {
using cd = std::complex<double>;

// The largest distance from each value of got to the nearest value of want.
template <class A, class B>
double farthest(const A& got, const B& want) {
  double worst = 0;
  for (Eigen::Index i = 0; i < got.size(); ++i) {
    double nearest = INFINITY;
    for (Eigen::Index j = 0; j < want.size(); ++j)
      nearest = std::min(nearest, double(std::abs(got(i) - want(j))));
    worst = std::max(worst, nearest);
  }
  return worst;
}
template <int N>
bool sorted(const Eigen::Matrix<cd, N, 1>& v) {
  for (int i = 1; i < N; ++i)
    if (v(i).real() < v(i - 1).real() || (v(i).real() == v(i - 1).real() && v(i).imag() < v(i - 1).imag()))
      return false;
  return true;
}
}  // namespace

TEST_CASE("eigenvalues: closed forms") {
  SECTION("a triangular matrix: its diagonal, sorted") {
    Eigen::Matrix<double, 5, 5> a;
    a << 3, 1, -2, 4, 5, 0, -1, 7, 2, 1, 0, 0, 0.5, 3, -2, 0, 0, 0, 2, 9, 0, 0, 0, 0, -4;
    const auto e = kane::eigenvalues(a.transpose().eval());  // lower triangular: the same values
    REQUIRE(e.status == kane::solve_status::ok);
    const double want[] = {-4, -1, 0.5, 2, 3};
    for (int i = 0; i < 5; ++i) CHECK(std::abs(e.values(i) - want[i]) < 1e-14);
  }
  SECTION("a turn by b scaled: a -+ i b") {
    Eigen::Matrix2d a;
    a << 0.3, -2, 2, 0.3;
    const auto e = kane::eigenvalues(a);
    REQUIRE(e.status == kane::solve_status::ok);
    CHECK(std::abs(e.values(0) - cd(0.3, -2)) < 1e-15);
    CHECK(std::abs(e.values(1) - cd(0.3, 2)) < 1e-15);
  }
  SECTION("a companion matrix: the roots of its polynomial") {
    // (x + 3)(x - 0.5)(x - 1)(x - 2)(x^2 + 2x + 5): roots -3, 0.5, 1, 2, -1 -+ 2i
    const cd roots[] = {-3, 0.5, 1, 2, {-1, -2}, {-1, 2}};
    std::array<cd, 7> c{1, 0, 0, 0, 0, 0, 0};  // coefficients, highest power first
    for (const cd& r : roots)
      for (std::size_t k = 6; k > 0; --k) c[k] -= r * c[k - 1];
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    for (int i = 0; i < 6; ++i) a(0, i) = -c[std::size_t(i + 1)].real();
    for (int i = 1; i < 6; ++i) a(i, i - 1) = 1;
    const auto e = kane::eigenvalues(a);
    REQUIRE(e.status == kane::solve_status::ok);
    const cd want[] = {-3, {-1, -2}, {-1, 2}, 0.5, 1, 2};
    for (int i = 0; i < 6; ++i) CHECK(std::abs(e.values(i) - want[i]) < 1e-12);
  }
  SECTION("T D T^-1 with D of known blocks") {
    Eigen::Matrix<double, 7, 7> d = Eigen::Matrix<double, 7, 7>::Zero();
    d(0, 0) = -2, d(1, 1) = 1e-3, d(2, 2) = 40;
    d(3, 3) = d(4, 4) = -0.5, d(3, 4) = 3, d(4, 3) = -3;  // -0.5 -+ 3i
    d(5, 5) = d(6, 6) = 7, d(5, 6) = 0.25, d(6, 5) = -0.25;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::Matrix<double, 7, 7> t = Eigen::Matrix<double, 7, 7>::Identity();
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) t(i, j) += 0.4 * u(gen);
    const Eigen::Matrix<double, 7, 7> a = t * d * t.inverse();
    const auto e = kane::eigenvalues(a);
    REQUIRE(e.status == kane::solve_status::ok);
    const cd want[] = {-2, {-0.5, -3}, {-0.5, 3}, 1e-3, {7, -0.25}, {7, 0.25}, 40};
    for (int i = 0; i < 7; ++i) CHECK(std::abs(e.values(i) - want[i]) < 1e-11 * 40);
  }
  SECTION(
      "zero, 1 x 1, and cyclic permutations: the roots of 1 (Francis's shifts stall, the exceptional ones go "
      "on)") {
    CHECK(kane::eigenvalues(Eigen::Matrix3d::Zero().eval()).values.cwiseAbs().maxCoeff() == 0);
    const auto one = kane::eigenvalues(Eigen::Matrix<double, 1, 1>::Constant(-2.5).eval());
    CHECK(one.values(0) == cd(-2.5, 0));
    const auto cyclic = [](auto p) {
      const int n = int(p.rows());
      p.setZero();
      for (int i = 0; i < n; ++i) p((i + 1) % n, i) = 1;
      const auto e = kane::eigenvalues(p);
      REQUIRE(e.status == kane::solve_status::ok);
      Eigen::VectorXcd want(n);
      for (int k = 0; k < n; ++k) want(k) = std::polar(1.0, 2 * M_PI * k / n);
      CHECK(farthest(e.values, want) < 1e-14);
      CHECK(farthest(want, e.values) < 1e-14);
    };
    cyclic(Eigen::Matrix3d());
    cyclic(Eigen::Matrix4d());
    cyclic(Eigen::Matrix<double, 5, 5>());
    cyclic(Eigen::Matrix<double, 8, 8>());
  }
}

TEST_CASE("eigenvalues: the benchmark bicycle of Meijaard et al. from the paper's matrices") {
  const auto paper = [](const double(&m)[2][2]) {
    return (Eigen::Matrix2d() << m[0][0], m[0][1], m[1][0], m[1][1]).finished();
  };
  const Eigen::Matrix2d m = paper(meijaard2007::M), c1 = paper(meijaard2007::C1),
                        k0 = paper(meijaard2007::K0), k2 = paper(meijaard2007::K2);
  const auto state_matrix = [&](double v) {
    Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
    a.topRightCorner<2, 2>().setIdentity();
    a.bottomLeftCorner<2, 2>() = -m.inverse() * (meijaard2007::g * k0 + v * v * k2);
    a.bottomRightCorner<2, 2>() = -m.inverse() * (v * c1);
    return a;
  };
  for (const auto& c : meijaard2007::eigenvalues) {  // the published table, in its order
    CAPTURE(c.v);
    const auto e = kane::eigenvalues(state_matrix(c.v));
    REQUIRE(e.status == kane::solve_status::ok);
    for (int i = 0; i < 4; ++i)
      CHECK(std::abs(e.values(i) - cd(c.re[i], c.im[i])) <
            1e-12 * std::max(1.0, std::abs(cd(c.re[i], c.im[i]))));
  }
  // the double eigenvalue where the two positive real ones meet: sensitive as sqrt(eps)
  const auto e = kane::eigenvalues(state_matrix(meijaard2007::bifurcation_speed));
  REQUIRE(e.status == kane::solve_status::ok);
  CHECK(std::abs(e.values(2) - meijaard2007::bifurcation_eigenvalue) < 1e-7);
  CHECK(std::abs(e.values(3) - meijaard2007::bifurcation_eigenvalue) < 1e-7);
}

TEST_CASE("eigenvalues: random matrices of 1 to 8 rows against Eigen's EigenSolver") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  // Graded: every third row 1e6 times, every other one 1e-6 times the rest. Eigen's solver does not
  // balance, and it loses up to 1e-9 of the largest eigenvalue there (against long double); kane's
  // balancing keeps 1e-12 of it.
  const auto check = [&](auto a, bool graded) {
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      for (Eigen::Index j = 0; j < a.cols(); ++j)
        a(i, j) = u(gen) * (graded ? std::pow(10.0, i % 3 == 2 ? 6 : -6 * (i % 2)) : 1.0);
    const auto e = kane::eigenvalues(a);
    REQUIRE(e.status == kane::solve_status::ok);
    CHECK(sorted(e.values));
    const Eigen::VectorXcd want = eigenvalues_of(a);
    const double scale = std::max(1.0, want.cwiseAbs().maxCoeff()), tol = graded ? 1e-9 : 1e-12;
    CHECK(farthest(e.values, want) < tol * scale);
    CHECK(farthest(want, e.values) < tol * scale);
    CHECK(std::abs(e.values.sum() - cd(a.trace(), 0)) < 1e-12 * scale * double(a.rows()));
    if (graded) {
      const auto wide = kane::eigenvalues(a.template cast<long double>().eval());
      REQUIRE(wide.status == kane::solve_status::ok);
      CHECK(farthest(e.values.template cast<std::complex<long double>>().eval(), wide.values) <
            1e-12L * scale);
    }
  };
  for (int k = 0; k < 50; ++k) {
    const bool graded = k % 2 == 1;
    check(Eigen::Matrix<double, 1, 1>(), graded);
    check(Eigen::Matrix<double, 2, 2>(), graded);
    check(Eigen::Matrix<double, 3, 3>(), graded);
    check(Eigen::Matrix<double, 4, 4>(), graded);
    check(Eigen::Matrix<double, 5, 5>(), graded);
    check(Eigen::Matrix<double, 6, 6>(), graded);
    check(Eigen::Matrix<double, 8, 8>(), graded);
  }
}

TEST_CASE("eigenvalues: not finite input and no convergence give a status and NaN") {
  Eigen::Matrix4d a;
  a << 1, 2, 3, 4, -1, 0.5, 2, 1, 3, -2, 1, 0, 0.5, 1, -1, 2;
  REQUIRE(kane::eigenvalues(a).status == kane::solve_status::ok);
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Eigen::Matrix4d b = a;
    b(2, 1) = bad;
    const auto e = kane::eigenvalues(b);
    CHECK(e.status == kane::solve_status::not_finite);
    CHECK(e.values.unaryExpr([](cd x) { return std::isnan(x.real()) && std::isnan(x.imag()); }).all());
  }
  const auto once = kane::eigenvalues(a, 1);  // one QR step per eigenvalue does not converge here
  CHECK(once.status == kane::solve_status::not_converged);
  CHECK(once.values.unaryExpr([](cd x) { return std::isnan(x.real()) && std::isnan(x.imag()); }).all());
}
