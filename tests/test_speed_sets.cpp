// Any speed set: u = Y q' + Z with Y's ones, sums and multiples of coordinate rates, in any order.
// q' and q'' against a dense solve of Y q' = u, angular velocities against an evaluator that reads
// q' itself, M and f against the transformed equations of u = q' (M_u = W^T M W, f_u = W^T (f - M W' u)),
// the absolute-angle double pendulum against its closed form, and the rolling disc's speeds reordered.
#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "../examples/models/disc.hpp"
#include "../examples/models/pendulum3d.hpp"
#include "trees.hpp"

using kane::dt;
using kane::q;

namespace {

// Y = P L U with L unit lower, U upper of diagonal +-1 or +-2, entries in -2..2: det Y != 0.
template <std::size_t N>
using imat = std::array<std::array<int, N>, N>;
struct lcg {
  std::uint64_t s;
  constexpr int next(int k) {  // 0..k-1
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return int((s >> 33) % std::uint64_t(k));
  }
};
template <std::size_t N>
constexpr imat<N> random_y(std::uint64_t seed) {
  lcg g{seed};
  imat<N> l{}, u{}, y{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      l[i][j] = i == j ? 1 : i > j ? g.next(5) - 2 : 0;
      u[i][j] = i == j ? (g.next(2) ? 1 : -1) * (1 + g.next(2)) : i < j ? g.next(5) - 2 : 0;
    }
  std::array<std::size_t, N> p{};
  for (std::size_t i = 0; i < N; ++i) p[i] = i;
  for (std::size_t i = N - 1; i > 0; --i) {
    const std::size_t j = std::size_t(g.next(int(i + 1)));
    const std::size_t t = p[i];
    p[i] = p[j], p[j] = t;
  }
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j)
      for (std::size_t k = 0; k < N; ++k) y[p[i]][j] += l[i][k] * u[k][j];
  return y;
}
// c q_J'
template <int C, std::size_t J>
constexpr auto term() {
  if constexpr (C == 0)
    return kane::zero_t{};
  else if constexpr (C == 1)
    return dt(q<J>);
  else if constexpr (C == -1)
    return -dt(q<J>);
  else
    return kane::constant<C>{} * dt(q<J>);
}
template <auto Y, std::size_t R>
constexpr auto row_of() {
  return [&]<std::size_t... J>(std::index_sequence<J...>) { return (term<Y[R][J], J + 1>() + ...); }
  (std::make_index_sequence<Y.size()>{});
}
template <auto Y, std::size_t... R>
auto speeds_of(std::index_sequence<R...>) -> kane::speeds<row_of<Y, R>()...>;
template <auto Y>
using speeds_from = decltype(speeds_of<Y>(std::make_index_sequence<Y.size()>{}));

template <std::size_t N>
struct frames_for {
  using type = kane::frames<trees::C>;  // q1..q3
};
template <>
struct frames_for<2> {
  using type = kane::frames<trees::B>;
};
template <>
struct frames_for<6> {
  using type = kane::frames<trees::C, trees::D, trees::E, trees::F>;  // q1..q6
};
template <class F, class Ev>
Eigen::Vector3d omega_in_n(const Ev& ev) {
  const kane::vec<trees::N> w = kane::express<trees::N>(kane::angular_velocity<trees::N, F>(), ev);
  return {w[0], w[1], w[2]};
}

// q', q'' and ^N w^C (and ^N w^F with six coordinates) of the speed set Y at random states.
template <auto Y>
void check_speed_set(std::mt19937& rng) {
  constexpr std::size_t n = Y.size();
  using St = kane::state<double, n, n>;
  using Fr = typename frames_for<n>::type;
  kane::evaluator<St, Fr, kane::level::acceleration, speeds_from<Y>> ev;
  kane::evaluator<St, Fr, kane::level::acceleration> by_rates;  // reads q' and q'' from the state
  Eigen::Matrix<double, int(n), int(n)> y;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) y(Eigen::Index(i), Eigen::Index(j)) = Y[i][j];
  std::uniform_real_distribution<double> d(-2, 2);
  for (int k = 0; k < 5; ++k) {
    St s;
    Eigen::Matrix<double, int(n), 1> u, ud;
    for (std::size_t i = 0; i < n; ++i) s.q[i] = d(rng), s.u[i] = d(rng), s.ud[i] = d(rng);
    for (std::size_t i = 0; i < n; ++i) u(Eigen::Index(i)) = s.u[i], ud(Eigen::Index(i)) = s.ud[i];
    const Eigen::Matrix<double, int(n), 1> qd = y.fullPivLu().solve(u), qdd = y.fullPivLu().solve(ud);
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto rates = ev.coordinate_rates(), accelerations = ev.template coordinate_rates<2>();
    for (std::size_t i = 0; i < n; ++i) {
      CHECK(std::fabs(rates[i] - qd(Eigen::Index(i))) < 1e-14 * (1 + qd.norm()));
      CHECK(std::fabs(accelerations[i] - qdd(Eigen::Index(i))) < 1e-14 * (1 + qdd.norm()));
      s.qd[i] = qd(Eigen::Index(i)), s.qdd[i] = qdd(Eigen::Index(i));
    }
    CHECK((ev.W() * y - decltype(y)::Identity()).norm() < 1e-15 * ev.W().norm() * y.norm());
    by_rates.update(s);
    using Last = std::conditional_t<n == 2, trees::B, trees::C>;
    CHECK((omega_in_n<Last>(ev) - omega_in_n<Last>(by_rates)).norm() < 1e-14 * (1 + qd.norm()));
    if constexpr (n == 6)
      CHECK((omega_in_n<trees::F>(ev) - omega_in_n<trees::F>(by_rates)).norm() < 1e-14 * (1 + qd.norm()));
  }
}
template <std::size_t N, std::uint64_t... Seed>
void check_random_sets(std::mt19937& rng) {
  (check_speed_set<random_y<N>(Seed)>(rng), ...);
}

namespace pd = models::pendulum3d;
using pd_state = pd::state;
// The 3D double pendulum's parameters, its damper c = 0 (a load in u_2 would differ between speed sets).
pd_state pendulum_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(0.5, 1.5), a(-1.5, 1.5);
  pd_state s;
  for (auto& p : s.p) p = d(rng);
  s.p[8] = s.p[9] = s.p[10] = 0.05;  // products of inertia small enough for a positive inertia
  s.p[14] = s.p[15] = s.p[16] = -0.04;
  s.p[17] = 9.81;
  s.p[19] = 0;
  for (auto& x : s.q) x = a(rng);
  return s;
}
// M and f at (q, q') with u = q': M_q, f_q.
struct qdot_equations {
  Eigen::Matrix2d M;
  Eigen::Vector2d f;
};
qdot_equations by_rates(const pd_state& at, const Eigen::Vector2d& qd) {
  pd_state s = at;
  s.u = {qd(0), qd(1)};
  kane::evaluator<pd_state, kane::frames<pd::B>, kane::level::acceleration, kane::qdot_speeds<2>> ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<pd::system>(ev);
  REQUIRE(eom.status == kane::solve_status::ok);
  return {eom.M, eom.f};
}
// W(q) of a speed set (q' = W u at u = 0 offsets)
template <class Sp>
Eigen::Matrix2d weights(pd_state s) {
  kane::evaluator<pd_state, kane::frames<pd::B>, kane::level::velocity, Sp> ev;
  ev.update(s);
  return ev.W();
}
// M_u = W^T M_q W and f_u = W^T (f_q - M_q W' u) with W' by central differences along q' = W u.
template <class Sp>
void check_pendulum_equations(std::mt19937& rng, double tol) {
  std::uniform_real_distribution<double> a(-1.5, 1.5);
  for (int k = 0; k < 5; ++k) {
    pd_state s = pendulum_state(rng);
    s.u = {a(rng), a(rng)};
    kane::evaluator<pd_state, kane::frames<pd::B>, kane::level::acceleration, Sp> ev;
    ev.update(s);
    const auto eom = kane::mass_matrix_and_forcing<pd::system>(ev);
    REQUIRE(eom.status == kane::solve_status::ok);
    const Eigen::Matrix2d w = ev.W();
    const Eigen::Vector2d u(s.u[0], s.u[1]), qd = w * u;
    const double h = 1e-6;
    pd_state plus = s, minus = s;
    for (int i = 0; i < 2; ++i) plus.q[std::size_t(i)] += h * qd(i), minus.q[std::size_t(i)] -= h * qd(i);
    const Eigen::Matrix2d wd = (weights<Sp>(plus) - weights<Sp>(minus)) / (2 * h);
    const auto [m, f] = by_rates(s, qd);
    CHECK((eom.M - w.transpose() * m * w).norm() < 1e-13 * m.norm());
    CHECK((eom.f - w.transpose() * (f - m * wd * u)).norm() < tol * (1 + f.norm()));
    // motion: q' = W u and u' solved, so q'' = W u' + W' u is the q'' of u = q'
    kane::motion<pd::system, decltype(ev)> rhs(s);
    std::array<double, 4> x{s.q[0], s.q[1], s.u[0], s.u[1]}, dx{};
    rhs(x, dx, 0.0);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    const Eigen::Vector2d qdd = w * Eigen::Vector2d(dx[2], dx[3]) + wd * u;
    CHECK((Eigen::Vector2d(dx[0], dx[1]) - qd).norm() < 1e-14 * (1 + qd.norm()));
    CHECK((qdd - m.llt().solve(f)).norm() < tol * (1 + qdd.norm()));
  }
}

}  // namespace

TEST_CASE("speed sets: sums of coordinate rates give the exact q'") {
  // A about n3 by q1, B about a1 by q2, C about b2 by q3; u = (1.3, -0.8, 0.5) at q = (0.3, 0.2, 0.1).
  using St = kane::state<double, 3, 3>;
  St s;
  s.q = {0.3, 0.2, 0.1};
  s.u = {1.3, -0.8, 0.5};
  const auto rates = [&](auto speed_set) {
    kane::evaluator<St, kane::frames<trees::C>, kane::level::velocity, decltype(speed_set)> ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    return ev.coordinate_rates();
  };
  const auto near = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::fabs(a[0] - b[0]) + std::fabs(a[1] - b[1]) + std::fabs(a[2] - b[2]) < 1e-14;
  };
  CHECK(near(rates(kane::speeds<dt(q<1>), dt(q<1>) + dt(q<2>), dt(q<3>)>{}), {1.3, -2.1, 0.5}));
  CHECK(near(rates(kane::speeds<dt(q<1>) + dt(q<2>), dt(q<2>), dt(q<3>)>{}), {2.1, -0.8, 0.5}));
  CHECK(near(rates(kane::speeds<dt(q<3>), dt(q<1>), dt(q<1>) + dt(q<2>)>{}), {-0.8, 1.3, 1.3}));
  CHECK(near(rates(kane::speeds<dt(q<1>), dt(q<1>) + dt(q<2>), dt(q<1>) + dt(q<2>) + dt(q<3>)>{}),
             {1.3, -2.1, 1.3}));
}

TEST_CASE("speed sets: random sums and multiples of up to six coordinate rates") {
  std::mt19937 rng(46);
  check_random_sets<2, 1>(rng);
  check_random_sets<4, 7>(rng);
  check_random_sets<6, 11>(rng);
}

TEST_CASE("speed sets: M and f of the 3D double pendulum follow the speeds") {
  std::mt19937 rng(7);
  // constant W: exact transforms
  check_pendulum_equations<kane::speeds<dt(q<1>), dt(q<1>) + dt(q<2>)>>(rng, 1e-13);
  // W of q: W' by central differences
  check_pendulum_equations<kane::speeds<dt(q<1>), kane::cos(q<1>) * dt(q<1>) + dt(q<2>)>>(rng, 1e-8);
}

TEST_CASE("speed sets: the planar double pendulum on absolute-angle rates") {
  // A about n3 by q1, B about a3 by q2; particles m1 at L1 a1, m2 at L1 a1 + L2 b1; gravity g n1.
  // With th1 = q1, th2 = q1 + q2 and u = (th1', th2'), Lagrange's equations in th give
  // M = [(m1 + m2) L1^2, m2 L1 L2 c; m2 L1 L2 c, m2 L2^2] with c = cos(th1 - th2), and
  // f = (-m2 L1 L2 s th2'^2 - (m1 + m2) g L1 sin th1, m2 L1 L2 s th1'^2 - m2 g L2 sin th2), s = sin(th1 -
  // th2).
  struct L1 : kane::parameter<1> {};
  struct L2 : kane::parameter<2> {};
  struct m1 : kane::parameter<3> {};
  struct m2 : kane::parameter<4> {};
  struct g : kane::parameter<5> {};
  struct A : kane::frame<trees::N, kane::simple<kane::axis::z, trees::q1>> {};
  struct B : kane::frame<A, kane::simple<kane::axis::z, trees::q2>> {};
  struct O : kane::origin<trees::N> {};
  struct P1 : kane::point<O, L1{} * kane::e<A, 1>> {};
  struct P2 : kane::point<P1, L2{} * kane::e<B, 1>> {};
  using system = kane::system<kane::particle<P1, m1{}>, kane::particle<P2, m2{}>,
                              kane::gravity<g{} * kane::e<trees::N, 1>>>;
  using St = kane::state<double, 2, 2, 5>;
  kane::evaluator<St, kane::frames<B>, kane::level::acceleration, kane::speeds<dt(q<1>), dt(q<1>) + dt(q<2>)>>
      ev;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-2, 2), p(0.5, 2);
  for (int k = 0; k < 10; ++k) {
    St s;
    s.q = {d(rng), d(rng)};
    s.u = {d(rng), d(rng)};
    s.p = {p(rng), p(rng), p(rng), p(rng), 9.81};
    ev.update(s);
    const auto eom = kane::mass_matrix_and_forcing<system>(ev);
    REQUIRE(eom.status == kane::solve_status::ok);
    const double l1 = s.p[0], l2 = s.p[1], ma = s.p[2], mb = s.p[3], gg = s.p[4];
    const double th1 = s.q[0], th2 = s.q[0] + s.q[1], c = std::cos(th1 - th2), sn = std::sin(th1 - th2);
    Eigen::Matrix2d m;
    m << (ma + mb) * l1 * l1, mb * l1 * l2 * c, mb * l1 * l2 * c, mb * l2 * l2;
    const Eigen::Vector2d f(-mb * l1 * l2 * sn * s.u[1] * s.u[1] - (ma + mb) * gg * l1 * std::sin(th1),
                            mb * l1 * l2 * sn * s.u[0] * s.u[0] - mb * gg * l2 * std::sin(th2));
    CHECK((eom.M - m).norm() < 1e-12);
    CHECK((eom.f - f).norm() < 1e-12);
  }
}

TEST_CASE("speed sets: the rolling disc's speeds in another order give the permuted M and f") {
  namespace dd = models::disc;
  using kane::dot;
  using kane::e;
  constexpr auto w = kane::angular_velocity<dd::N, dd::R>();
  using St = kane::state<double, 5, 5, 3>;
  // the usual u = (w.l1, w.l2, w.l3, q4', q5'); the others list the same speeds as usual[perm[i]]
  const auto equations = [](auto speed_set, const St& usual, const std::array<int, 5>& perm) {
    St s = usual;
    for (std::size_t i = 0; i < 5; ++i) s.u[i] = usual.u[std::size_t(perm[i])];
    kane::evaluator<St, kane::frames<dd::R>, kane::level::acceleration, decltype(speed_set)> ev;
    ev.update(s);
    const auto eom = kane::mass_matrix_and_forcing<dd::system>(ev);
    REQUIRE(eom.status == kane::solve_status::ok);
    Eigen::Matrix<double, 5, 5> m;  // back in the usual order
    Eigen::Matrix<double, 5, 1> f;
    for (int i = 0; i < 5; ++i) {
      f(perm[std::size_t(i)]) = eom.f(i);
      for (int j = 0; j < 5; ++j) m(perm[std::size_t(i)], perm[std::size_t(j)]) = eom.M(i, j);
    }
    return std::pair{m, f};
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1.2, 1.2);
  for (int k = 0; k < 5; ++k) {
    St s;
    for (std::size_t i = 0; i < 5; ++i) s.q[i] = d(rng), s.u[i] = d(rng);
    s.p = {0.5, 2.0, 9.81};
    const auto [m, f] = equations(dd::speeds5{}, s, {0, 1, 2, 3, 4});
    const auto [m1, f1] = equations(
        kane::speeds<dt(q<4>), dot(w, e<dd::L, 1>), dot(w, e<dd::L, 2>), dot(w, e<dd::L, 3>), dt(q<5>)>{}, s,
        {3, 0, 1, 2, 4});
    const auto [m2, f2] = equations(
        kane::speeds<dot(w, e<dd::L, 2>), dot(w, e<dd::L, 1>), dot(w, e<dd::L, 3>), dt(q<4>), dt(q<5>)>{}, s,
        {1, 0, 2, 3, 4});
    CHECK((m1 - m).norm() < 1e-12);
    CHECK((f1 - f).norm() < 1e-12);
    CHECK((m2 - m).norm() < 1e-12);
    CHECK((f2 - f).norm() < 1e-12);
  }
}

TEST_CASE("speed sets: the linearization follows the speeds") {
  // x = (q, u) with u = (q1', q1' + q2'): A against central differences of kane::motion
  using sp = kane::speeds<dt(q<1>), dt(q<1>) + dt(q<2>)>;
  using Ev = kane::evaluator<pd_state, kane::frames<pd::B>, kane::level::acceleration, sp>;
  std::mt19937 rng(11);
  pd_state s = pendulum_state(rng);
  s.u = {0.4, -0.9};
  const auto lin = kane::linearize<pd::system, Ev>(s);
  REQUIRE(lin.status == kane::solve_status::ok);
  kane::motion<pd::system, Ev> rhs(s);
  const std::array<double, 4> x{s.q[0], s.q[1], s.u[0], s.u[1]};
  const double h = 1e-6;
  for (std::size_t j = 0; j < 4; ++j) {
    std::array<double, 4> up = x, down = x, dup{}, ddown{};
    up[j] += h, down[j] -= h;
    rhs(up, dup, 0.0);
    rhs(down, ddown, 0.0);
    for (std::size_t i = 0; i < 4; ++i)
      CHECK(lin.A(Eigen::Index(i), Eigen::Index(j)) ==
            Approx((dup[i] - ddown[i]) / (2 * h)).margin(1e-7).epsilon(1e-7));
  }
}
