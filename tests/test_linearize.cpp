// Linearization (linearization/): jets against central differences of the
// nonlinear right-hand side (3D double pendulum), and the upright rolling disc
// against its closed form: M = diag(I_d + m r^2, I_s + m r^2, I_d), the lean
// stiffness -m g r, the gyroscopic couplings, and lean eigenvalues
// lambda^2 = 4 (g - 3 r W^2) / (5 r) for the uniform thin disc spinning at W; the leaning disc
// away from equilibrium against central differences of constrained_motion and of M~ u' - f~.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Cholesky>
#include <kane/linearization.hpp>

#include "../examples/models/disc.hpp"
#include "../examples/models/pendulum3d.hpp"
#include "eigenvalues.hpp"

namespace {
namespace pd = models::pendulum3d;
namespace d = models::disc;
using disc_state = kane::state<double, 5, 5, 3>;
using disc_evaluator = kane::evaluator<disc_state, kane::frames<d::R>, kane::level::acceleration, d::speeds5>;

pd::state pendulum_state() {
  pd::state s;
  s.q = {0.3, -0.5};
  s.u = {0.7, 0.2};
  s.p = {1,    0.8,  2,    1.5,   0.5,    0.1,   0.12, 0.03, 0.01, 0.02, -0.01,
         0.09, 0.08, 0.02, 0.005, -0.004, 0.003, 9.81, 3,    0.4,  0.2};
  return s;
}
}  // namespace

TEST_CASE("linearize: the 3D double pendulum's A and B against central differences") {
  const pd::state s = pendulum_state();
  const auto lin = kane::linearize<pd::system, pd::evaluator, kane::inputs<pd::p<19>>>(s);  // input: k
  REQUIRE(lin.status == kane::solve_status::ok);
  const auto rate = [&](const pd::state& x) {
    kane::motion<pd::system, pd::evaluator> f(x);
    std::array<double, 4> y{x.q[0], x.q[1], x.u[0], x.u[1]}, dy;
    f(y, dy, 0.0);
    return dy;
  };
  const auto base = rate(s);
  for (int i = 0; i < 4; ++i) CHECK(lin.rate(i) == Approx(base[std::size_t(i)]).epsilon(1e-14));
  const double h = 1e-5;
  for (int j = 0; j < 5; ++j) {
    pd::state plus = s, minus = s;
    double* slot = j < 2 ? &plus.q[std::size_t(j)] : j < 4 ? &plus.u[std::size_t(j - 2)] : &plus.p[18];
    double* other = j < 2 ? &minus.q[std::size_t(j)] : j < 4 ? &minus.u[std::size_t(j - 2)] : &minus.p[18];
    *slot += h, *other -= h;
    const auto up = rate(plus), down = rate(minus);
    for (int i = 0; i < 4; ++i) {
      const double fd = (up[std::size_t(i)] - down[std::size_t(i)]) / (2 * h);
      const double exact = j < 4 ? lin.A(i, j) : lin.B(i, 0);
      CHECK(exact == Approx(fd).margin(1e-8).epsilon(1e-8));
    }
  }
  // the kinematic rows: q' = u
  CHECK(lin.A.topRows(2) == (Eigen::Matrix<double, 2, 4>() << 0, 0, 1, 0, 0, 0, 0, 1).finished());
}

TEST_CASE("linearize: a NaN state gives not_finite") {
  pd::state s = pendulum_state();
  s.p[0] = std::numeric_limits<double>::quiet_NaN();
  CHECK(kane::linearize<pd::system, pd::evaluator, kane::inputs<pd::p<19>>>(s).status ==
        kane::solve_status::not_finite);
}

TEST_CASE("linearize: the upright rolling disc, Kane's closed form") {
  const double r = 0.3, m = 1.2, g = 9.81, Id = m * r * r / 4, Is = m * r * r / 2;
  for (double spin : {2.0, 5.0, 8.0}) {
    CAPTURE(spin);
    disc_state s;
    s.p = {r, m, g};
    s.q = {0.2, 0, 0.5, 1, 2};  // yaw, lean, spin angle and contact place do not matter
    s.u = {0, spin, 0, 0, 0};
    const auto eq = kane::linearize_equations<d::system, d::rolling, disc_evaluator>(s);
    REQUIRE(eq.status == kane::solve_status::ok);
    Eigen::Matrix3d M = Eigen::Vector3d(Id + m * r * r, Is + m * r * r, Id).asDiagonal();
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    C(0, 2) = -(Is + m * r * r) * spin;  // lean: - (I_s + m r^2) W u3
    C(2, 0) = Is * spin;                 // about l3: I_s W u1
    Eigen::Matrix<double, 3, 5> K = Eigen::Matrix<double, 3, 5>::Zero();
    K(0, 1) = -m * g * r;
    CHECK((eq.M - M).cwiseAbs().maxCoeff() < 1e-15);
    CHECK((eq.C - C).cwiseAbs().maxCoeff() < 1e-15);
    CHECK((eq.K - K).cwiseAbs().maxCoeff() < 1e-15);
    // rows and columns by speed and coordinate: u1 (lean rate), u2 (spin), u3; K over q1..q5
    using E = std::remove_cvref_t<decltype(eq)>;
    static_assert(E::row(kane::u<1>) == 0 && E::row(kane::u<3>) == 2 && E::index(kane::q<2>) == 1);
    CHECK(eq.K(E::row(kane::u<1>), E::index(kane::q<2>)) == Approx(-m * g * r).epsilon(1e-15));
    CHECK(eq.C(E::row(kane::u<3>), E::row(kane::u<1>)) == Approx(Is * spin).epsilon(1e-15));

    const auto lin = kane::linearize_constrained<d::system, d::rolling, disc_evaluator>(s);
    REQUIRE(lin.status == kane::solve_status::ok);
    using L = std::remove_cvref_t<decltype(lin)>;  // x = (q1 .. q5, u1, u2, u3)
    static_assert(L::index(kane::q<5>) == 4 && L::index(kane::u<1>) == 5 && L::index(kane::u<3>) == 7);
    CHECK(lin.A(L::index(kane::q<2>), L::index(kane::u<1>)) == 1);  // q2' = u1
    const double lambda2 = 4 * (g - 3 * r * spin * spin) / (5 * r);
    const Eigen::VectorXcd ev = eigenvalues_of(lin.A);
    // the lean pair: the eigenvalues of largest modulus, +-sqrt(lambda2)
    double largest = 0;
    for (int i = 0; i < 8; ++i) largest = std::max(largest, std::abs(ev(i)));
    CHECK(largest == Approx(std::sqrt(std::abs(lambda2))).epsilon(1e-13));
    for (int i = 0; i < 8; ++i)
      if (std::abs(ev(i)) > 1e-6) CHECK(std::abs(ev(i) * ev(i) - lambda2) < 1e-12 * std::abs(lambda2));
  }
}

TEST_CASE("linearize_equations and linearize_constrained: the rolling disc away from equilibrium") {
  // lean 0.4 with lean, spin and heading rates: u_ind' is not zero, so M~ u_ind' enters C and K
  disc_state s;
  s.p = {0.3, 1.2, 9.81};
  s.q = {0.2, 0.4, 0.5, 1, 2};
  s.u = {0.7, 5, -0.3, 0, 0};
  const std::array<double, 8> x0{0.2, 0.4, 0.5, 1, 2, 0.7, 5, -0.3};  // (q, u_ind)
  kane::constrained_motion<d::system, d::rolling, disc_evaluator> rhs(s);
  const auto at = [&](const std::array<double, 8>& x) {  // x' and M~, f~, as a user reads them
    std::array<double, 8> dx{};
    rhs(x, dx, 0.0);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    const auto eq = kane::reduced_mass_matrix_and_forcing<d::system, d::rolling>(
                        rhs.evaluator(), kane::solve_constraints<d::rolling>(rhs.evaluator()))
                        .reduced;
    return std::pair{Eigen::Map<const Eigen::Matrix<double, 8, 1>>(dx.data()).eval(), eq};
  };
  const auto [r0, e0] = at(x0);
  const Eigen::Vector3d ud = e0.M.ldlt().solve(e0.f);
  REQUIRE(ud.cwiseAbs().maxCoeff() > 1);
  const auto eq = kane::linearize_equations<d::system, d::rolling, disc_evaluator>(s);
  const auto lin = kane::linearize_constrained<d::system, d::rolling, disc_evaluator>(s);
  REQUIRE(eq.status == kane::solve_status::ok);
  REQUIRE(lin.status == kane::solve_status::ok);
  CHECK((eq.M - e0.M).cwiseAbs().maxCoeff() < 1e-14);
  CHECK((lin.rate - r0).cwiseAbs().maxCoeff() < 1e-13 * r0.cwiseAbs().maxCoeff());
  // central differences: A = dx'/dx; K over q1..q5 and C over u1..u3 = d(M~ u_ind' - f~)/dx, u_ind' held
  const double h = 1e-6;
  for (std::size_t j = 0; j < 8; ++j) {
    CAPTURE(j);
    std::array<double, 8> xp = x0, xm = x0;
    xp[j] += h, xm[j] -= h;
    const auto [rp, ep] = at(xp);
    const auto [rm, em] = at(xm);
    const Eigen::Matrix<double, 8, 1> da = (rp - rm) / (2 * h);
    CHECK((lin.A.col(Eigen::Index(j)) - da).cwiseAbs().maxCoeff() <
          1e-7 * std::max(1.0, da.cwiseAbs().maxCoeff()));
    const Eigen::Vector3d de = ((ep.M * ud - ep.f) - (em.M * ud - em.f)) / (2 * h);
    const Eigen::Vector3d got =
        j < 5 ? Eigen::Vector3d(eq.K.col(Eigen::Index(j))) : eq.C.col(Eigen::Index(j - 5));
    CHECK((got - de).cwiseAbs().maxCoeff() < 1e-7 * std::max(1.0, de.cwiseAbs().maxCoeff()));
  }
  // a NaN mass: not_finite, and every matrix NaN
  s.p[1] = std::numeric_limits<double>::quiet_NaN();
  const auto bad_lin = kane::linearize_constrained<d::system, d::rolling, disc_evaluator>(s);
  CHECK(bad_lin.status == kane::solve_status::not_finite);
  CHECK(bad_lin.A.array().isNaN().all());
  CHECK(bad_lin.rate.array().isNaN().all());
  const auto bad_eq = kane::linearize_equations<d::system, d::rolling, disc_evaluator>(s);
  CHECK(bad_eq.status == kane::solve_status::not_finite);
  CHECK(bad_eq.M.array().isNaN().all());
  CHECK(bad_eq.C.array().isNaN().all());
  CHECK(bad_eq.K.array().isNaN().all());
}
