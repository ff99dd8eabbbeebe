// A floating base on Euler parameters with body rates carrying two spatial arms (floating_arms.hpp):
// with eight-link arms (22 speeds, a free joint), kane::linearize against central differences of
// kane::motion (1e-7 relative), its Euler parameters' columns along the turns of B; the analytical
// derivatives of inverse and forward dynamics against central differences along the motion of each
// speed (1e-7), and kane::linearize by them against jets through the whole evaluator (1e-10), also for
// the base alone, whose u' takes Kane's sums; kane::linearize_tangent against its dense formula; M against
// the Hessian of the kinetic energy and x' against the conservation of energy; kane::inverse_dynamics on
// Kane's sums (rates in N's components, not a free joint) against M u' - f.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include <kane/kane.hpp>

#include "allocations.hpp"
#include "differences.hpp"
#include "floating_arms.hpp"

namespace {
namespace fa = floating_arms;

template <class Model>
struct arms {
  using state = typename Model::state;
  static constexpr std::size_t nq = state::nq, nu = state::nu, nx = nq + nu, nr = state::nr;
  using vector_x = Eigen::Matrix<double, int(nx), 1>;
  // x' of kane::motion at x and the inputs r
  static vector_x rates(const state& s, const std::array<double, nx>& x, const std::array<double, nr>& r) {
    kane::motion<typename Model::system, typename Model::speeds> rhs(s);
    rhs.inputs() = r;
    std::array<double, nx> dx{};
    rhs(x, dx, s.t);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    return Eigen::Map<const vector_x>(dx.data());
  }
};
}  // namespace

TEST_CASE("linearize: a floating base with two eight-link arms against central differences", "[linearize]") {
  using model = fa::model<8>;
  using A = arms<model>;
  constexpr std::size_t nq = A::nq, nu = A::nu, nx = A::nx, nr = A::nr;
  STATIC_REQUIRE(nu == 22);
  const auto s = fa::sample<model::state>(5);
  const long before = allocations::count();
  const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
  const long allocated = allocations::count() - before;
  CHECK(allocated == 0);
  REQUIRE(lin.status == kane::solve_status::ok);
  std::array<double, nx> x{};
  for (std::size_t i = 0; i < nq; ++i) x[i] = s.q[i];
  for (std::size_t i = 0; i < nu; ++i) x[nq + i] = s.u[i];
  CHECK(relative(lin.rate, A::rates(s, x, s.r)) < 1e-12);

  Eigen::Matrix<double, int(nx), int(nx + nr)> diff;
  const double h = 1e-6;
  for (std::size_t j = 0; j < nx + nr; ++j) {
    std::array<double, nx> xp = x, xm = x;
    std::array<double, nr> rp = s.r, rm = s.r;
    (j < nx ? xp[j] : rp[j - nx]) += h;
    (j < nx ? xm[j] : rm[j - nx]) -= h;
    diff.col(Eigen::Index(j)) = (A::rates(s, xp, rp) - A::rates(s, xm, rm)) / (2 * h);
  }
  // u' takes the Euler parameters' columns along the turns of B: none along |e|
  const auto t = fa::tangent(s);
  CHECK(relative(lin.A * t, diff.leftCols<int(nx)>() * t) < 1e-7);
  CHECK(relative(lin.A.topRows<int(nq)>(), diff.topLeftCorner<int(nq), int(nx)>()) < 1e-7);
  CHECK(relative(lin.B, diff.rightCols<int(nr)>()) < 1e-7);
  const Eigen::Vector4d e(s.q[0], s.q[1], s.q[2], s.q[3]);
  CHECK((lin.A.bottomLeftCorner<int(nu), 4>() * e).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("dynamics derivatives: a floating base with two eight-link arms against differences and jets",
          "[derivatives]") {
  using model = fa::model<8>;
  constexpr std::size_t nq = model::state::nq, nu = model::state::nu;
  auto s = fa::sample<model::state>(5);
  for (std::size_t i = 0; i < 4; ++i) s.q[i] *= 1.2;  // |e| = 1.2: q' and its rows hold at any norm
  const auto errors = fa::derivatives_against_differences<model>(s, 1e-5);
  for (double x : errors) CHECK(x < 1e-7);
  // kane::linearize by the derivatives against jets in batches through the whole evaluator
  const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
  const auto jets = kane::detail::linearize_in_batches<model::system, model::evaluator, model::inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  REQUIRE(jets.status == kane::solve_status::ok);
  const auto t = fa::tangent(s);
  CHECK(relative(lin.A * t, jets.A * t) < 1e-10);
  CHECK(relative(lin.A.topRows<int(nq)>(), jets.A.topRows<int(nq)>()) < 1e-10);
  CHECK(relative(lin.B, jets.B) < 1e-10);
  CHECK(relative(lin.rate, jets.rate) < 1e-12);
  model::evaluator ev;
  ev.update(s);
  const auto d = kane::forward_dynamics_derivatives<model::system>(ev);
  REQUIRE(d.status == kane::solve_status::ok);
  const Eigen::Matrix<double, int(nu), int(2 * nu)> tangent_rows = jets.A.bottomRows<int(nu)>() * t;
  CHECK(relative(d.dud_dq, tangent_rows.leftCols<int(nu)>()) < 1e-10);
  CHECK(relative(d.dud_du, tangent_rows.rightCols<int(nu)>()) < 1e-10);
}

namespace lone {  // the base alone, a thrust and torques: its dynamics by Kane's sums, M known
using namespace floating_arms;
constexpr auto w = kane::angular_velocity<N, B>();
struct model {
  using system =
      kane::system<base, kane::gravity<literal(-9.81) * e<N, 3>>, kane::force<Bo, kane::r<1> * e<B, 3>>,
                   kane::torque<B, kane::r<2> * e<B, 1> + kane::r<3> * e<B, 2>>>;
  using speeds = kane::speeds<dot(w, e<B, 1>), dot(w, e<B, 2>), dot(w, e<B, 3>), dt(q<5>{}), dt(q<6>{}),
                              dt(q<7>{}), kane::unit_norm<B>>;
  using state = kane::state_of<system, speeds>;
  using evaluator = kane::system_evaluator<system, speeds>;
  using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>>;
};
}  // namespace lone

TEST_CASE(
    "dynamics derivatives: a free body alone, its dynamics by Kane's sums, against differences and jets",
    "[derivatives]") {
  using model = lone::model;
  static_assert(!kane::detail::recursive_form<model::system, model::evaluator> &&
                kane::detail::free_joint<model::system, model::evaluator>);
  const auto s = fa::sample<model::state>(13);
  for (double x : fa::derivatives_against_differences<model>(s)) CHECK(x < 1e-7);
  const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
  const auto jets = kane::detail::linearize_in_batches<model::system, model::evaluator, model::inputs>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  const auto t = fa::tangent(s);
  CHECK(relative((lin.A * t).eval(), (jets.A * t).eval()) < 1e-10);
  CHECK(relative(lin.A.topRows<7>(), jets.A.topRows<7>()) < 1e-10);
  CHECK(relative(lin.B, jets.B) < 1e-10);
}

TEST_CASE("linearize_tangent: a floating base's A~ and B~ are L (A T - T') and L B of kane::linearize",
          "[linearize]") {
  using model = fa::model<8>;
  constexpr std::size_t nq = model::state::nq, nu = model::state::nu, nx = nq + nu, n = nx - 1;
  for (double norm : {1.0, 1.3}) {  // L = 4 G^T / |e|^2, and L G = 1, at any norm of e
    auto s = fa::sample<model::state>(3);
    for (std::size_t i = 0; i < 4; ++i) s.q[i] *= norm;
    const auto lin = kane::linearize<model::system, model::evaluator, model::inputs>(s);
    const auto tangent = kane::linearize_tangent<model::system, model::evaluator, model::inputs>(s);
    REQUIRE(tangent.status == kane::solve_status::ok);
    // dense, by plain loops: T and L of the base's G(e), T' of G(e')
    const auto rows = Eigen::Index(nx), cols = Eigen::Index(n);
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(rows, cols), td = t, l = Eigen::MatrixXd::Zero(cols, rows);
    const Eigen::Vector4d e(s.q[0], s.q[1], s.q[2], s.q[3]);
    t.topLeftCorner(4, 3) = kane::detail::attitude_map(e(0), e(1), e(2), e(3));
    td.topLeftCorner(4, 3) = kane::detail::attitude_map(lin.rate(0), lin.rate(1), lin.rate(2), lin.rate(3));
    l.topLeftCorner(3, 4) = 4 * t.topLeftCorner(4, 3).transpose() / e.squaredNorm();
    t.bottomRightCorner(rows - 4, rows - 4).setIdentity();
    l.bottomRightCorner(rows - 4, rows - 4).setIdentity();
    const auto times = [](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
      Eigen::MatrixXd z = Eigen::MatrixXd::Zero(x.rows(), y.cols());
      for (Eigen::Index i = 0; i < x.rows(); ++i)
        for (Eigen::Index j = 0; j < y.cols(); ++j)
          for (Eigen::Index k = 0; k < x.cols(); ++k) z(i, j) += x(i, k) * y(k, j);
      return z;
    };
    const Eigen::MatrixXd a = lin.A, b = lin.B;
    CHECK(relative(Eigen::MatrixXd(tangent.A), times(l, times(a, t) - td)) < 1e-14);
    CHECK(relative(Eigen::MatrixXd(tangent.B), times(l, b)) < 1e-14);
    CHECK(relative(times(l, t), Eigen::MatrixXd::Identity(cols, cols)) < 1e-14);
  }
}

TEST_CASE(
    "a floating base with two eight-link arms: M is the Hessian of T, and T + V is conserved without inputs",
    "[dynamics]") {
  using model = fa::model<8>;
  using A = arms<model>;
  constexpr std::size_t nq = A::nq, nu = A::nu, nx = A::nx;
  auto s = fa::sample<model::state>(7);
  s.r = {0.0, 0.0, 0.0};
  model::evaluator ev;
  ev.update(s);
  const auto e = kane::mass_matrix_and_forcing<model::system>(ev);
  REQUIRE(e.status == kane::solve_status::ok);
  // T at the speeds v: M_ij = T(e_i + e_j) - T(e_i) - T(e_j)
  const auto energy = [&](const auto& v) {
    model::state at = s;
    at.u = v;
    model::evaluator x;
    x.update(at);
    return kane::kinetic_energy<model::system>(x);
  };
  Eigen::Matrix<double, int(nu), int(nu)> hessian;
  std::array<double, nu> single{};
  for (std::size_t i = 0; i < nu; ++i) {
    std::array<double, nu> v{};
    v[i] = 1.0;
    single[i] = energy(v);
  }
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nu; ++j) {
      std::array<double, nu> v{};
      v[i] += 1.0, v[j] += 1.0;
      hessian(Eigen::Index(i), Eigen::Index(j)) = i == j ? 2 * single[i] : energy(v) - single[i] - single[j];
    }
  CHECK(relative(e.M, hessian) < 1e-13);

  // d(T + V)/dt along x' of kane::motion, by a central difference along x'
  std::array<double, nx> x{};
  for (std::size_t i = 0; i < nq; ++i) x[i] = s.q[i];
  for (std::size_t i = 0; i < nu; ++i) x[nq + i] = s.u[i];
  const A::vector_x rate = A::rates(s, x, s.r);
  const auto total = [&](double h) {
    model::state at = s;
    for (std::size_t i = 0; i < nq; ++i) at.q[i] = x[i] + h * rate(Eigen::Index(i));
    for (std::size_t i = 0; i < nu; ++i) at.u[i] = x[nq + i] + h * rate(Eigen::Index(nq + i));
    model::evaluator y;
    y.update(at);
    return kane::kinetic_energy<model::system>(y) + kane::potential_energy<model::system>(y);
  };
  const double h = 1e-5, power = (total(h) - total(-h)) / (2 * h);
  Eigen::Matrix<double, int(nu), 1> u;
  for (std::size_t i = 0; i < nu; ++i) u(Eigen::Index(i)) = s.u[i];
  CHECK(std::abs(power) < 1e-7 * (1 + std::abs(u.dot(e.f))));
}

TEST_CASE("inverse dynamics on Kane's sums: tau = M u' - f, zero at u' = M^-1 f", "[dynamics]") {
  // the base's rates in N's components: not a free joint, Kane's sums
  constexpr auto w = kane::angular_velocity<fa::N, fa::B>();
  using speeds = kane::speeds<dot(w, fa::e<fa::N, 1>), dot(w, fa::e<fa::N, 2>), dot(w, fa::e<fa::N, 3>),
                              kane::dt(fa::q<5>{}), kane::dt(fa::q<6>{}), kane::dt(fa::q<7>{}),
                              kane::dt(fa::q<8>{}), kane::dt(fa::q<9>{}), kane::unit_norm<fa::B>>;
  using system = fa::model<1>::system;
  using evaluator = kane::system_evaluator<system, speeds>;
  static_assert(!kane::detail::recursive_form<system, evaluator>);
  constexpr std::size_t nu = evaluator::nu;
  auto s = fa::sample<kane::state_of<system, speeds>>(11);
  evaluator ev;
  ev.update(s);
  const auto e = kane::mass_matrix_and_forcing<system>(ev);
  Eigen::Matrix<double, int(nu), 1> ud;
  for (std::size_t i = 0; i < nu; ++i) ud(Eigen::Index(i)) = s.ud[i];
  const auto [tau, status] = kane::inverse_dynamics<system>(ev);
  REQUIRE(status == kane::solve_status::ok);
  CHECK(relative(tau, e.M * ud - e.f) < 1e-12);
  CHECK(relative(kane::forcing<system>(ev).f, e.f) < 1e-12);

  const auto [solved, ok] = kane::forward_dynamics<system>(ev);
  REQUIRE(ok == kane::solve_status::ok);
  for (std::size_t i = 0; i < nu; ++i) s.ud[i] = solved(Eigen::Index(i));
  ev.update(s);
  CHECK(kane::inverse_dynamics<system>(ev).tau.cwiseAbs().maxCoeff() <
        1e-10 * (1 + e.f.cwiseAbs().maxCoeff()));
}
