// Jets (linearization/jet.hpp) and common subexpressions (evaluation/memo.hpp):
// the block and positive definite solves of jets against elimination and Cholesky
// carried out on jets, nan_unless on numbers, jets and matrices, and the rolling
// disc's differentiated constraints evaluated on jets with and without recalling
// their repeated subtrees.
#include <catch2/catch.hpp>
#include <cmath>

#include <Eigen/Cholesky>
#include <kane/linearization.hpp>

#include "../examples/models/disc.hpp"

namespace {
using J = kane::jet<double, 3>;
using M4 = Eigen::Matrix<J, 4, 4>;

M4 jet_matrix(double rank_defect) {
  M4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double v = std::sin(1.0 + 3 * i + 7 * j) + (i == j ? 2.0 : 0.0);
      m(i, j) =
          J(v) + J::variable(0.0, 0) * J(std::cos(i + 2.0 * j)) + J::variable(0.0, 2) * J(0.1 * (i - j));
    }
  for (int j = 0; j < 4; ++j) m(3, j) = m(3, j) * J(1 - rank_defect) + (m(0, j) + m(1, j)) * J(rank_defect);
  return m;
}
}  // namespace

TEST_CASE("jet: a jet is zero when value-initialised, as a double") {
  const J z{};
  CHECK(z.v == 0.0);
  for (std::size_t k = 0; k < 3; ++k) CHECK(z.part(k) == 0.0);
}

TEST_CASE("jet: the solves that jets overload equal elimination and Cholesky carried out on jets") {
  // a coupled block: y = X t from the values' inverse, dy = X (dt - dB y), against B^-1 t on jets
  const M4 m = jet_matrix(0.0);
  Eigen::Matrix<J, 4, 1> t, y;
  for (int i = 0; i < 4; ++i) t(i) = J(1.0 + i) + J::variable(0.0, 1) * J(0.5 * i - 1) + J::variable(0.0, 2);
  M4 x, inverse;
  REQUIRE(factor_block(m, x, J(-1)));  // the jets' overloads (argument-dependent lookup)
  REQUIRE(kane::detail::invert(m, inverse));
  y = solve_block(x, m, t);
  const Eigen::Matrix<J, 4, 1> expected = inverse * t;
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(y(i).v - expected(i).v) < 1e-13);
    for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(y(i).part(k) - expected(i).part(k)) < 1e-12);
  }
  const M4 s = jet_matrix(1.0);
  CHECK_FALSE(factor_block(s, x, J(-1)));
  // positive definite: Cholesky of the values and M dx = df - dM x, against Eigen's LLT on jets
  const M4 spd = m.transpose() * m;
  Eigen::Matrix<J, 4, 1> u = Eigen::Matrix<J, 4, 1>::Constant(J(7.0));
  REQUIRE(solve_positive_definite(spd, t, u));
  const Eigen::Matrix<J, 4, 1> llt = Eigen::LLT<M4>(spd).solve(t);
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(u(i).v - llt(i).v) < 1e-12);
    for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(u(i).part(k) - llt(i).part(k)) < 1e-11);
  }
  // not positive definite: false, and x untouched
  M4 indefinite = spd;
  indefinite(2, 2) = J(-1.0);
  u.setConstant(J(7.0));
  CHECK_FALSE(solve_positive_definite(indefinite, t, u));
  CHECK(u(0).v == 7.0);
  CHECK(u(0).part(1) == 0.0);
}

TEST_CASE("memo: repeated subtrees are found once, and recalling them changes no number") {
  using kane::q;
  constexpr auto a = q<1> * q<2>;
  constexpr auto x = a * a + kane::sqrt(a);
  using plan = kane::detail::memo_plan<decltype(x)>;
  // q1 q2; the sum and its square occur once. (g++ with -fsanitize=null cannot compare the nodes' keys
  // at compile time: there no node is recalled.)
  constexpr bool on = kane::detail::keys_compare;
  STATIC_REQUIRE(plan::repeated.n == (on ? 1 : 0));
  STATIC_REQUIRE((!on || plan::index<std::remove_cvref_t<decltype(a)>>() == 0));

  namespace d = models::disc;
  using St = kane::state<J, 5, 5, 1>;
  kane::evaluator<St, kane::frames<d::R>, kane::level::acceleration, d::speeds5> ev;
  St s;
  s.q = {J::variable(0.3, 0), J::variable(0.4, 1), J(0.1), J(0.2), J(-0.5)};
  s.u = {J::variable(0.7, 2), J(-0.2), J(1.3), J(0.4), J(0.6)};
  s.ud = {J(0.1), J(0.2), J(-0.3), J(0.0), J(0.5)};
  s.p = {J(0.5)};
  ev.update(s);
  REQUIRE(ev.status() == kane::solve_status::ok);
  constexpr auto c0 = kane::dt(std::get<0>(d::rolling::equations));
  constexpr auto c1 = kane::dt(std::get<1>(d::rolling::equations));
  STATIC_REQUIRE((kane::detail::memo_plan<decltype(c0), decltype(c1)>::repeated.n > 0) == on);
  const J plain0 = kane::detail::eval_scalar(c0, ev), plain1 = kane::detail::eval_scalar(c1, ev);
  J memo0, memo1;
  kane::detail::with_common_subexpressions<decltype(c0), decltype(c1)>(ev, [&](const auto& e) {
    memo0 = kane::detail::eval_scalar(c0, e);
    memo1 = kane::detail::eval_scalar(c1, e);
  });
  CHECK(memo0 == plain0);  // every part, exactly: the same operations on the same numbers
  CHECK(memo1 == plain1);
  CHECK(std::abs(plain0.part(0)) + std::abs(plain1.part(2)) >
        1e-3);  // the derivatives are not trivially zero
}

TEST_CASE(
    "held coordinates: the disc's contact position is read by nothing, and A's columns of it are zero") {
  namespace d = models::disc;
  using St = kane::state<double, 5, 5, 3>;
  using Ev = kane::evaluator<St, kane::frames<d::R>, kane::level::acceleration, d::speeds5>;
  // yaw q1, lean q2 and spin q3 turn frames; q4, q5 (the contact point) enter no velocity
  STATIC_REQUIRE(kane::detail::coordinates_held<d::system, d::rolling, Ev, void>() == 0b00111);
  STATIC_REQUIRE(kane::detail::directions<d::system, d::rolling, Ev, void>.n == 3);
  St s;
  s.q = {0.3, 0.4, 0.1, 0.2, -0.5};
  s.u = {0.7, -0.2, 1.3, 0, 0};
  s.p = {0.5, 2.0, 9.81};
  const auto lin = kane::linearize_constrained<d::system, d::rolling, Ev>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  for (Eigen::Index i = 0; i < lin.A.rows(); ++i) {
    CHECK(lin.A(i, 3) == 0.0);
    CHECK(lin.A(i, 4) == 0.0);
  }
  // the held columns against central differences of the nonlinear right-hand side
  kane::constrained_motion<d::system, d::rolling, Ev> f(s);
  const auto rate = [&](std::array<double, 8> x) {
    std::array<double, 8> dx;
    f(x, dx, 0.0);
    return dx;
  };
  const std::array<double, 8> x0{0.3, 0.4, 0.1, 0.2, -0.5, 0.7, -0.2, 1.3};
  for (std::size_t j : {0u, 1u, 5u}) {
    auto xp = x0, xm = x0;
    xp[j] += 1e-6, xm[j] -= 1e-6;
    const auto fp = rate(xp), fm = rate(xm);
    for (std::size_t i = 0; i < 8; ++i)
      CHECK(std::abs((fp[i] - fm[i]) / 2e-6 - lin.A(Eigen::Index(i), Eigen::Index(j))) < 1e-7);
  }
}

TEST_CASE("nan_unless: numbers keep every bit when ok and all matrices and jets turn NaN when not") {
  using kane::detail::nan_unless;
  double z = -0.0, inf = HUGE_VAL, a = 2.5;
  const auto keep = nan_unless<double>(true);
  keep(z), keep(inf), keep(a);
  CHECK(std::signbit(z));
  CHECK(z == 0.0);
  CHECK(inf == HUGE_VAL);
  CHECK(a == 2.5);
  nan_unless<double>(false)(a);
  CHECK(std::isnan(a));
  Eigen::Matrix<double, 2, 3> m = Eigen::Matrix<double, 2, 3>::Constant(-1.5);
  keep(m);
  CHECK(m(1, 2) == -1.5);
  nan_unless<double>(false)(m);
  CHECK(m.array().isNaN().all());
  J j = J(3.0) + J::variable(0.0, 1);
  nan_unless<J>(true)(j);
  CHECK(j.v == 3.0);
  CHECK(j.part(1) == 1.0);
  nan_unless<J>(false)(j);
  CHECK(std::isnan(j.v));
  Eigen::Matrix<J, 2, 2> mj = Eigen::Matrix<J, 2, 2>::Constant(J(4.0));
  nan_unless<J>(true)(mj);
  CHECK(mj(1, 0).v == 4.0);
  nan_unless<J>(false)(mj);
  for (int i = 0; i < 4; ++i) CHECK(std::isnan(mj(i).v));
}
