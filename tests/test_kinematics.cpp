#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "data/sympy_kinematics.hpp"
#include "trees.hpp"

using namespace trees;
using kane::e;
using kane::vec;

namespace {
struct P1 : kane::parameter<1> {};
struct P2 : kane::parameter<2> {};
inline constexpr P1 L1;
inline constexpr P2 L2;

template <class F, class S = double>
bool near(const vec<F, S>& v, const double (&x)[3], double tol) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(double(v[i]) - x[i]) <= tol * (1 + std::abs(x[i])))) return false;
  return true;
}
template <class F>
std::string show(const vec<F>& v) {
  return std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]);
}

template <class St, class C>
void load(St& s, const C& c) {
  for (std::size_t i = 0; i < St::nq; ++i) s.q[i] = c.q[i], s.qd[i] = c.qd[i], s.qdd[i] = c.qdd[i];
}

// The chain point r = L1 c1 + L2 c3.
struct O : kane::origin<N> {};
struct R : kane::point<O, L1 * e<C, 1> + L2 * e<C, 3>> {};

// The planar double pendulum.
struct DA : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct DB : kane::frame<DA, kane::simple<kane::axis::z, q2>> {};
struct Q1 : kane::point<O, L1 * e<DA, 1>> {};
struct Q2 : kane::point<Q1, L2 * e<DB, 1>> {};

// The spherical pendulum: P = O - L b3.
struct SA : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct SB : kane::frame<SA, kane::simple<kane::axis::x, q2>> {};
struct SP : kane::point<O, -L1 * e<SB, 3>> {};

// The 6-revolute arm: axes z, y, y, x, y, x.
struct B1 : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B2 : kane::frame<B1, kane::simple<kane::axis::y, q2>> {};
struct B3 : kane::frame<B2, kane::simple<kane::axis::y, q3>> {};
struct B4 : kane::frame<B3, kane::simple<kane::axis::x, q4>> {};
struct B5 : kane::frame<B4, kane::simple<kane::axis::y, q5>> {};
struct B6 : kane::frame<B5, kane::simple<kane::axis::x, q6>> {};
struct J2 : kane::point<O, 0.3 * e<B1, 1>> {};
struct J3 : kane::point<J2, 0.25 * e<B2, 1>> {};
struct J4 : kane::point<J3, 0.2 * e<B3, 1>> {};
struct J5 : kane::point<J4, 0.15 * e<B4, 1>> {};
struct J6 : kane::point<J5, 0.1 * e<B5, 1>> {};
struct End : kane::point<J6, 0.05 * e<B6, 1>> {};

using chain_state = kane::state<double, 3, 3, 2>;
using chain_eval = kane::evaluator<chain_state, kane::frames<C>>;
}  // namespace

TEST_CASE("kinematics: the chain N -z-> A -x-> B -y-> C against SymPy") {
  for (const auto& c : sympy_kin::chain) {
    chain_state s;
    load(s, c);
    s.p = {c.L[0], c.L[1]};
    chain_eval ev;
    ev.update(s);
    const double(&dcm)[9] = c.NPC;
    const auto NPC = kane::direction_cosines<N, C>(s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(NPC(i, j) == Approx(dcm[3 * i + j]).margin(1e-14));
    const auto w = kane::angular_velocity<N, C>();
    CHECK(near(kane::express<N>(w, ev), c.wNC_N, 1e-13));
    CHECK(near(kane::express<C>(w, ev), c.wNC_C, 1e-13));
    CHECK(near(kane::express<N>(kane::angular_acceleration<N, C>(), ev), c.aNC_N, 1e-13));
    CHECK(near(kane::express<C>(kane::angular_velocity<C, A>(), ev), c.wCA_C, 1e-13));
    const auto r = L1 * e<C, 1> + L2 * e<C, 3>;
    CHECK(near(kane::express<N>(r, ev), c.r_N, 1e-13));
    CHECK(near(kane::express<N>(kane::dt<N>(r), ev), c.v_N, 1e-13));
    CHECK(near(kane::express<N>(kane::dt<N>(kane::dt<N>(r)), ev), c.a_N, 1e-13));
    CHECK(near(kane::express<N>(kane::velocity<N, R>(), ev), c.v_N, 1e-13));
    CHECK(near(kane::express<N>(kane::acceleration<N, R>(), ev), c.a_N, 1e-13));
  }
}

// The outward pass skips the numbers of e_F1, e_F2, e_F3 in N that are 0 or 1 at every state
// (detail/patterned.hpp): N -z-> A keeps e_A3 = n3 and zero third components of e_A1, e_A2;
// a turn about A's x (y) keeps e_A1 (e_A2) and mixes the other two columns.
namespace patterns {
using enum kane::detail::entry;
using columns = std::array<kane::detail::entry, 9>;
constexpr columns identity{one, zero, zero, zero, one, zero, zero, zero, one};
constexpr columns about_z{other, other, zero, other, other, zero, zero, zero, one};
static_assert(kane::detail::turned_columns(identity, 2) == about_z);
static_assert(kane::detail::turned_columns(about_z, 0) ==
              columns{other, other, zero, other, other, other, other, other, other});
static_assert(kane::detail::turned_columns(about_z, 1) ==
              columns{other, other, other, other, other, zero, other, other, other});
}  // namespace patterns

TEST_CASE("kinematics: the double pendulum against SymPy and closed forms") {
  using St = kane::state<double, 2, 2, 2>;
  for (const auto& c : sympy_kin::double_pendulum) {
    St s;
    load(s, c);
    s.p = {c.L[0], c.L[1]};
    kane::evaluator<St, kane::frames<DB>> ev;
    ev.update(s);
    const auto v1 = kane::express<N>(kane::velocity<N, Q1>(), ev);
    const auto v2 = kane::express<N>(kane::velocity<N, Q2>(), ev);
    const auto a2 = kane::express<N>(kane::acceleration<N, Q2>(), ev);
    CHECK(near(v1, c.v1_N, 1e-13));
    CHECK(near(kane::express<N>(kane::acceleration<N, Q1>(), ev), c.a1_N, 1e-13));
    CHECK(near(v2, c.v2_N, 1e-13));
    CHECK(near(a2, c.a2_N, 1e-13));
    // x = L1 c1 + L2 c12, y = L1 s1 + L2 s12, differentiated by hand.
    const double l1 = c.L[0], l2 = c.L[1], c1 = std::cos(c.q[0]), s1 = std::sin(c.q[0]);
    const double c12 = std::cos(c.q[0] + c.q[1]), s12 = std::sin(c.q[0] + c.q[1]);
    const double w1 = c.qd[0], w = c.qd[0] + c.qd[1], w1d = c.qdd[0], wd = c.qdd[0] + c.qdd[1];
    const double v2x = -l1 * s1 * w1 - l2 * s12 * w, v2y = l1 * c1 * w1 + l2 * c12 * w;
    const double a2x = -l1 * (c1 * w1 * w1 + s1 * w1d) - l2 * (c12 * w * w + s12 * wd);
    const double a2y = l1 * (-s1 * w1 * w1 + c1 * w1d) + l2 * (-s12 * w * w + c12 * wd);
    CHECK(kane::is_approx(v2, vec<N>(v2x, v2y, 0), 1e-13));
    CHECK(kane::is_approx(a2, vec<N>(a2x, a2y, 0), 1e-13));
    // the unit tangent t = v / |v| and its N-derivative (a - t (t . a)) / |v|
    const auto tangent = kane::normalized(kane::velocity<N, Q2>());
    const Eigen::Vector3d v(v2x, v2y, 0), a(a2x, a2y, 0), t = v / v.norm();
    CHECK((kane::express<N>(tangent, ev).eigen() - t).norm() < 1e-14);
    CHECK((kane::express<N>(kane::dt<N>(tangent), ev).eigen() - (a - t * t.dot(a)) / v.norm()).norm() <
          1e-13 * (1 + a.norm() / v.norm()));
  }
}

TEST_CASE("kinematics: the spherical pendulum against SymPy") {
  using St = kane::state<double, 2, 2, 1>;
  for (const auto& c : sympy_kin::spherical) {
    St s;
    load(s, c);
    s.p = {c.L};
    kane::evaluator<St, kane::frames<SB>> ev;
    ev.update(s);
    CHECK(near(kane::express<N>(kane::position<O, SP>(), ev), c.r_N, 1e-13));
    CHECK(near(kane::express<N>(kane::velocity<N, SP>(), ev), c.v_N, 1e-13));
    CHECK(near(kane::express<SB>(kane::velocity<N, SP>(), ev), c.v_B, 1e-13));
    CHECK(near(kane::express<N>(kane::acceleration<N, SP>(), ev), c.a_N, 1e-13));
  }
}

// An evaluator for the quantities asked: the frames they read (e_B6,1 = e_B5,1, and B6's w and
// alpha one edge below B5) and the lowest level that gives them, with SymPy's numbers.
TEST_CASE("kinematics: evaluator_for holds the frames and the level its expressions read") {
  using St = kane::state<double, 6>;
  constexpr auto r = kane::position<O, End>();
  constexpr auto v = kane::velocity<N, End>();
  constexpr auto w = kane::angular_velocity<N, B6>();
  constexpr auto a = kane::acceleration<N, End>();
  using pose = kane::reads<r>;
  using velocity = kane::reads<w, v>;
  using acceleration = kane::reads<a, kane::e<B6, 2>>;
  static_assert(pose::needed == kane::level::pose && velocity::needed == kane::level::velocity &&
                acceleration::needed == kane::level::acceleration);
  static_assert(kane::detail::size<kane::evaluator_for<St, velocity>::evaluator_type::closure>::value ==
                6);  // N, B1 .. B5
  static_assert(kane::detail::size<kane::evaluator_for<St, acceleration>::evaluator_type::closure>::value ==
                7);
  for (const auto& c : sympy_kin::arm) {
    St s;
    load(s, c);
    kane::evaluator_for<St, pose> ev_pose;
    kane::evaluator_for<St, velocity> ev_velocity;
    kane::evaluator_for<St, acceleration> ev_acceleration;
    ev_pose.update(s), ev_velocity.update(s), ev_acceleration.update(s);
    CHECK(near(kane::express<N>(r, ev_pose), c.r_N, 1e-13));
    CHECK(near(kane::express<N>(v, ev_velocity), c.v_N, 1e-13));
    CHECK(near(kane::express<N>(w, ev_velocity), c.w_N, 1e-13));
    CHECK(near(kane::express<N>(a, ev_acceleration), c.a_N, 1e-13));
  }
}

TEST_CASE("kinematics: evaluator_for holds the values of its reads, as the evaluator computes them") {
  using St = kane::state<double, 6>;
  constexpr auto r = kane::position<O, End>();
  constexpr auto v = kane::velocity<N, End>();
  constexpr auto w = kane::angular_velocity<N, B6>();
  constexpr auto a = kane::acceleration<N, End>();
  constexpr auto alpha = kane::angular_acceleration<N, B6>();
  constexpr auto height = kane::dot(r, e<N, 3>);  // a scalar read
  constexpr auto rate = kane::dt(kane::q<2>);
  using all =
      kane::reads<r, v, w, a, alpha, height, rate, kane::partials_of(v), kane::partials_of(w), e<B6, 2>>;
  kane::evaluator_for<St, all> ev;
  CHECK(!ev.updated());
  CHECK(std::isnan(kane::express<N>(a, ev)[1]));  // NaN before the first update
  CHECK(std::isnan(kane::partial_velocities<N>(v, ev)(2, 5)));
  kane::evaluator<St, kane::frames<B6>> full;
  for (const auto& c : sympy_kin::arm) {
    St s;
    load(s, c);
    ev.update(s), full.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    CHECK(near(kane::express<N>(r, ev), c.r_N, 1e-13));
    CHECK(near(kane::express<N>(v, ev), c.v_N, 1e-13));
    CHECK(near(kane::express<N>(w, ev), c.w_N, 1e-13));
    CHECK(near(kane::express<N>(a, ev), c.a_N, 1e-13));
    CHECK(near(kane::express<N>(alpha, ev), c.alpha_N, 1e-13));
    CHECK(kane::evaluate(height, ev) == Approx(c.r_N[2]).margin(1e-14));
    CHECK(kane::evaluate(rate, ev) == c.qd[1]);
    // the tables and a unit vector against the evaluator of the frames, and J u = v
    const Eigen::Matrix<double, 3, 6> V = kane::partial_velocities<N>(v, ev);
    CHECK((V - kane::partial_velocities<N>(v, full)).norm() < 1e-14);
    CHECK((kane::partial_velocities<N>(w, ev) - kane::partial_velocities<N>(w, full)).norm() < 1e-14);
    CHECK((V * Eigen::Map<const Eigen::Matrix<double, 6, 1>>(c.qd) - kane::express<N>(v, ev).eigen()).norm() <
          1e-13);
    CHECK((kane::express<N>(e<B6, 2>, ev).eigen() - full.axes<B6>().col(1)).norm() < 1e-15);
  }
  // A state that is not finite: the status says so and the values are NaN.
  St s;
  load(s, sympy_kin::arm[0]);
  s.qd[3] = std::numeric_limits<double>::infinity();
  ev.update(s);
  CHECK(ev.updated());
  CHECK(ev.status() == kane::solve_status::not_finite);
  CHECK(!std::isfinite(kane::express<N>(v, ev)[0]));
  // A read of the type of a held one with other numbers in it: NaN, never the held value.
  constexpr auto twice = 2.0 * e<B1, 1>;
  kane::evaluator_for<St, kane::reads<twice>> ev_twice;
  load(s, sympy_kin::arm[0]);
  ev_twice.update(s);
  CHECK(kane::express<N>(twice, ev_twice)[0] == Approx(2 * std::cos(s.q[0])));
  CHECK(std::isnan(kane::express<N>(3.0 * e<B1, 1>, ev_twice)[0]));
}

TEST_CASE("kinematics: without a speed set q' comes from s.qd or s.u, number by number") {
  // six coordinates (a block of four and a pair, or three pairs) and three (a pair and one)
  const auto check = []<std::size_t NQ>(auto frame, std::integral_constant<std::size_t, NQ>) {
    using F = decltype(frame);
    using St = kane::state<double, NQ>;
    const auto w = kane::angular_velocity<N, F>();
    St by_qd, by_u, mixed;
    for (std::size_t i = 0; i < NQ; ++i) {
      const double q = 0.1 * double(i + 1), rate = 0.3 - 0.2 * double(i);
      by_qd.q[i] = by_u.q[i] = mixed.q[i] = q;
      by_qd.qd[i] = rate, by_u.u[i] = rate;
      (i % 2 ? mixed.qd[i] : mixed.u[i]) = rate;
    }
    kane::evaluator<St, kane::frames<F>, kane::level::velocity> ev;
    ev.update(by_qd);
    const auto expected = kane::express<N>(w, ev);
    REQUIRE(ev.status() == kane::solve_status::ok);
    for (const St& s : {by_u, mixed}) {
      ev.update(s);
      CHECK(ev.status() == kane::solve_status::ok);
      CHECK(kane::express<N>(w, ev) == expected);
    }
    for (std::size_t i = 0; i < NQ; ++i) {  // a second, different number in one coordinate
      St s = by_qd;
      s.u[i] = s.qd[i] + 1;
      ev.update(s);
      CHECK(ev.status() == kane::solve_status::conflicting_rates);
      s.u[i] = s.qd[i];  // the same number twice is no conflict
      ev.update(s);
      CHECK(ev.status() == kane::solve_status::ok);
    }
    St s = by_qd;
    s.qd[0] = -0.0;  // -0 in s.qd and 0 in s.u: s.qd, with its sign
    ev.update(s);
    CHECK(std::signbit(ev.template coordinate_value<1, 1>()));
    // q'' from s.qdd, or from s.ud with q' from s.qd (u zero): one test of u and u' decides
    const auto alpha = kane::angular_acceleration<N, F>();
    kane::evaluator<St, kane::frames<F>, kane::level::acceleration> acc;
    St by_qdd = by_qd, by_ud = by_qd, both_conflict = by_qd;
    for (std::size_t i = 0; i < NQ; ++i)
      by_qdd.qdd[i] = by_ud.ud[i] = both_conflict.qdd[i] = 0.5 + 0.1 * double(i);
    both_conflict.ud[NQ - 1] = 7.0;
    acc.update(by_qdd);
    REQUIRE(acc.status() == kane::solve_status::ok);
    const auto expected_alpha = kane::express<N>(alpha, acc);
    acc.update(by_ud);
    CHECK(acc.status() == kane::solve_status::ok);
    CHECK(kane::express<N>(alpha, acc) == expected_alpha);
    acc.update(both_conflict);
    CHECK(acc.status() == kane::solve_status::conflicting_rates);
    by_ud.u[0] = std::numeric_limits<double>::quiet_NaN();  // u NaN beside a given q': not ok
    acc.update(by_ud);
    CHECK(acc.status() != kane::solve_status::ok);
  };
  check(B6{}, std::integral_constant<std::size_t, 6>{});
  check(C{}, std::integral_constant<std::size_t, 3>{});
}

TEST_CASE("kinematics: the end point of a 6-revolute arm against SymPy") {
  using St = kane::state<double, 6>;
  for (const auto& c : sympy_kin::arm) {
    St s;
    load(s, c);
    kane::evaluator<St, kane::frames<B6>> ev;
    ev.update(s);
    INFO(show(kane::express<N>(kane::position<O, End>(), ev)));
    CHECK(near(kane::express<N>(kane::position<O, End>(), ev), c.r_N, 1e-13));
    CHECK(near(kane::express<N>(kane::velocity<N, End>(), ev), c.v_N, 1e-13));
    CHECK(near(kane::express<N>(kane::acceleration<N, End>(), ev), c.a_N, 1e-13));
    CHECK(near(kane::express<N>(kane::angular_velocity<N, B6>(), ev), c.w_N, 1e-13));
    CHECK(near(kane::express<N>(kane::angular_acceleration<N, B6>(), ev), c.alpha_N, 1e-13));
  }
}

namespace {
// q(t) = q + q' t + q'' t^2 / 2 around t = 0.
template <class St>
St at_time(const St& s, long double h) {
  St r = s;
  for (std::size_t i = 0; i < St::nq; ++i) {
    r.q[i] = s.q[i] + s.qd[i] * h + s.qdd[i] * h * h / 2;
    r.qd[i] = s.qd[i] + s.qdd[i] * h;
  }
  return r;
}
template <class Ev, class St, class X>
vec<N, long double> in_N(const X& x, const St& s) {
  Ev ev;
  ev.update(s);
  return kane::express<N>(x, ev);
}
}  // namespace

TEST_CASE("kinematics: velocities and accelerations equal finite differences of positions (long double)") {
  using St = kane::state<long double, 6, 6, 2>;
  using Ev = kane::evaluator<St, kane::frames<B6, C, E, F, DB>>;
  std::mt19937 rng(23);
  std::uniform_real_distribution<long double> d(-2, 2);
  const long double h = 1e-4L;
  for (int k = 0; k < 100; ++k) {
    St s;
    for (int i = 0; i < 6; ++i) s.q[i] = d(rng), s.qd[i] = d(rng), s.qdd[i] = d(rng);
    s.p = {1.1L, 0.6L};
    const St sp = at_time(s, h), sm = at_time(s, -h);
    auto check = [&](auto point) {
      using P = decltype(point);
      const auto r = kane::position<O, P>();
      const auto r0 = in_N<Ev>(r, s), rp = in_N<Ev>(r, sp), rm = in_N<Ev>(r, sm);
      const auto v = in_N<Ev>(kane::velocity<N, P>(), s);
      const auto a = in_N<Ev>(kane::acceleration<N, P>(), s);
      for (int i = 0; i < 3; ++i) {
        CHECK(double(v[i]) == Approx(double((rp[i] - rm[i]) / (2 * h))).margin(1e-8));
        CHECK(double(a[i]) == Approx(double((rp[i] - 2 * r0[i] + rm[i]) / (h * h))).margin(1e-5));
      }
    };
    check(End{});
    check(R{});
    check(Q2{});
    // A point on the branch with a constant axis and rotation sequences.
    struct T : kane::point<O, L1 * e<E, 2> + kane::sin(kane::q<3>) * e<F, 1> + kane::q<4> * e<D, 3>> {};
    check(T{});
  }
}

TEST_CASE("kinematics: definition (8) of the angular velocity equals the addition theorem (10)") {
  using St = kane::state<long double, 6>;
  std::mt19937 rng(29);
  std::uniform_real_distribution<long double> d(-2, 2);
  const long double h = 1e-5L;
  for (int k = 0; k < 100; ++k) {
    St s;
    for (int i = 0; i < 6; ++i) s.q[i] = d(rng), s.qd[i] = d(rng);
    kane::evaluator<St, kane::frames<C, E, F>> ev;
    ev.update(s);
    // (8): w = b1 (db2/dt . b3) + b2 (db3/dt . b1) + b3 (db1/dt . b2), with the
    // A-derivatives of the unit vectors of F from finite differences of ^A P^F.
    const St sp = at_time(s, h), sm = at_time(s, -h);
    const auto P = kane::direction_cosines<A, F>(s).eigen();  // row i: f_i in A
    const Eigen::Matrix<long double, 3, 3> dP =
        (kane::direction_cosines<A, F>(sp).eigen() - kane::direction_cosines<A, F>(sm).eigen()) / (2 * h);
    const vec<F, long double> w8(dP.row(1).dot(P.row(2)), dP.row(2).dot(P.row(0)), dP.row(0).dot(P.row(1)));
    // (10): ^A w^F = ^A w^B + ^B w^C + ^C w^F, summed at compile time.
    const auto chained =
        kane::angular_velocity<A, B>() + kane::angular_velocity<B, C>() + kane::angular_velocity<C, F>();
    static_assert(std::is_same_v<decltype(chained), const kane::angular_velocity_of<A, F>>);
    const auto direct = kane::express<F>(kane::angular_velocity<A, B>(), ev) +
                        kane::express<F>(kane::angular_velocity<B, C>(), ev) +
                        kane::express<F>(kane::angular_velocity<C, F>(), ev);
    for (int i = 0; i < 3; ++i) {
      CHECK(double(kane::express<F>(chained, ev)[i]) == Approx(double(w8[i])).margin(1e-8));
      CHECK(double(direct[i]) == Approx(double(w8[i])).margin(1e-8));
    }
    // ^F w^A = -^A w^F
    CHECK(kane::is_approx(kane::express<F>(kane::angular_velocity<F, A>(), ev),
                          -kane::express<F>(chained, ev), 1e-15L));
  }
}

TEST_CASE("kinematics: transport theorem, eq. (13), eq. (6)-(7) and the two- and one-point theorems") {
  using St = kane::state<double, 6, 6, 2>;
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> d(-2, 2);
  // A point moving on C, a point fixed in C, a vector with terms of three frames.
  struct QC : kane::point<O, L1 * e<A, 1>> {};
  struct PC : kane::point<QC, L2 * e<C, 2> + 0.5 * e<C, 3>> {};
  struct PM : kane::point<QC, kane::q<4> * e<C, 1> + kane::sin(kane::q<5>) * e<C, 2>> {};
  const auto p = L1 * kane::sin(kane::q<2>) * e<A, 1> + kane::q<4> * e<C, 2> - L2 * e<E, 3>;
  // Fixed points are found at compile time; their velocity is a type-level zero.
  struct OA : kane::origin<A> {};
  struct PA : kane::point<OA, L1 * e<A, 1> + 2.0 * e<A, 2>> {};
  static_assert(kane::fixed_in_v<PA, A> && !kane::fixed_in_v<PA, N> && kane::fixed_in_v<O, N>);
  static_assert(!kane::fixed_in_v<PC, C> && !kane::fixed_in_v<QC, A>);
  static_assert(kane::is_zero_vector_v<decltype(kane::velocity<A, PA>())>);
  static_assert(kane::is_zero_vector_v<decltype(kane::velocity<N, O>())>);
  for (int k = 0; k < 200; ++k) {
    St s;
    for (int i = 0; i < 6; ++i) s.q[i] = d(rng), s.qd[i] = d(rng), s.qdd[i] = d(rng);
    s.p = {0.7, 1.3};
    kane::evaluator<St, kane::frames<C, E>> ev;
    ev.update(s);
    auto N_ = [&](const auto& x) { return kane::express<N>(x, ev); };
    // (12): ^N dp/dt = ^C dp/dt + ^N w^C x p
    CHECK(kane::is_approx(N_(kane::dt<N>(p)),
                          N_(kane::dt<C>(p) + kane::cross(kane::angular_velocity<N, C>(), p)), 1e-12));
    // (13): ^N alpha^C = ^N d(^N w^C)/dt = ^C d(^N w^C)/dt
    const auto w = kane::angular_velocity<N, C>();
    CHECK(kane::is_approx(N_(kane::dt<N>(w)), N_(kane::angular_acceleration<N, C>()), 1e-12));
    CHECK(kane::is_approx(N_(kane::dt<C>(w)), N_(kane::angular_acceleration<N, C>()), 1e-12));
    CHECK(kane::is_approx(N_(kane::dt<A>(kane::angular_velocity<A, E>())),
                          N_(kane::angular_acceleration<A, E>()), 1e-12));
    // (7): ^A dp/dt = sum_r ^A dp/dq_r q_r' (no explicit time)
    const auto sum = kane::diff<A>(p, kane::q<1>) * kane::dt(kane::q<1>) +
                     kane::diff<A>(p, kane::q<2>) * kane::dt(kane::q<2>) +
                     kane::diff<A>(p, kane::q<3>) * kane::dt(kane::q<3>) +
                     kane::diff<A>(p, kane::q<4>) * kane::dt(kane::q<4>) +
                     kane::diff<A>(p, kane::q<5>) * kane::dt(kane::q<5>) +
                     kane::diff<A>(p, kane::q<6>) * kane::dt(kane::q<6>);
    CHECK(kane::is_approx(N_(sum), N_(kane::dt<A>(p)), 1e-12));
    // Two points whose separation is fixed in C; a point moving on C.
    CHECK(kane::is_approx(N_(kane::velocity<N, PC>()), N_(kane::two_point_velocity<N, C, QC, PC>()), 1e-12));
    CHECK(kane::is_approx(N_(kane::acceleration<N, PC>()), N_(kane::two_point_acceleration<N, C, QC, PC>()),
                          1e-12));
    CHECK(kane::is_approx(N_(kane::velocity<N, PM>()), N_(kane::one_point_velocity<N, C, QC, PM>()), 1e-12));
    CHECK(kane::is_approx(N_(kane::acceleration<N, PM>()), N_(kane::one_point_acceleration<N, C, QC, PM>()),
                          1e-12));
  }
}

TEST_CASE("kinematics: numbers of point positions live in types, so derived quantities are empty") {
  // 0.05 * e<B6, 1> as a template argument becomes fixed<0.05> * e<B6, 1>.
  STATIC_REQUIRE(std::is_empty_v<decltype(End::position)>);
  STATIC_REQUIRE(std::is_empty_v<decltype(kane::velocity<N, End>())>);
  STATIC_REQUIRE(std::is_empty_v<decltype(kane::acceleration<N, End>())>);
  STATIC_REQUIRE(std::is_empty_v<decltype(kane::partial_velocity<kane::qdot_speeds<6>>(
                     kane::velocity<N, End>(), kane::u<3>))>);
  // A literal written at run time stays a literal.
  STATIC_REQUIRE(!std::is_empty_v<decltype(0.05 * e<B6, 1>)>);
  // The frozen number is the written one.
  using F = decltype(End::position.s);
  STATIC_REQUIRE(F::value == 0.05);
}

TEST_CASE("kinematics: angular velocity and acceleration one edge below the evaluator's frames") {
  // C turns from B about b2: ^N w^C and ^N alpha^C come from B's and the edge's rates, and e_C2 = e_B2.
  std::mt19937 rng(71);
  for (int k = 0; k < 50; ++k) {
    auto s = random_state(rng);
    for (auto& x : s.qd) x = std::uniform_real_distribution<double>(-2, 2)(rng);
    for (auto& x : s.qdd) x = std::uniform_real_distribution<double>(-2, 2)(rng);
    kane::evaluator<state6, kane::frames<B>> up_to_b;
    kane::evaluator<state6, kane::frames<C>> up_to_c;
    up_to_b.update(s);
    up_to_c.update(s);
    const auto w = kane::angular_velocity<N, C>();
    const auto a = kane::angular_acceleration<N, C>();
    CHECK(kane::is_approx(kane::express<N>(w, up_to_b), kane::express<N>(w, up_to_c), 1e-14));
    CHECK(kane::is_approx(kane::express<N>(a, up_to_b), kane::express<N>(a, up_to_c), 1e-14));
    CHECK(kane::is_approx(kane::express<N>(kane::e<C, 2>, up_to_b), kane::express<N>(kane::e<C, 2>, up_to_c),
                          0.0));
  }
}

TEST_CASE("kinematics: ^A w^B - ^A w^C = ^C w^B, reversed chains, and the evaluator's copy of its state") {
  state6 s;
  s.q = {0.3, -0.7, 1.1, 0, 0, 0};
  s.qd = {0.5, 1.5, -2.0, 0, 0, 0};
  kane::evaluator<state6, kane::frames<C>> ev;
  CHECK(!ev.updated());
  // before the first update every result is NaN, never a read of memory not written
  CHECK(std::isnan(kane::express<N>(e<C, 2>, ev)[0]));
  ev.update(s);
  CHECK(ev.updated());
  const auto wNA = kane::express<N>(kane::angular_velocity<N, A>(), ev);
  const auto wNC = kane::express<N>(kane::angular_velocity<N, C>(), ev);
  // ^N w^A - ^N w^C = ^C w^A = -(q2' a1 + q3' b2) (B about a1 = x by q2, C about b2 = y by q3)
  const auto diff = kane::express<N>(kane::angular_velocity<N, A>() - kane::angular_velocity<N, C>(), ev);
  const auto wCA = kane::express<N>(kane::angular_velocity<C, A>(), ev);
  const auto a1 = kane::express<N>(e<A, 1>, ev), b2 = kane::express<N>(e<B, 2>, ev);
  for (int i = 0; i < 3; ++i) {
    CHECK(diff[i] == Approx(wNA[i] - wNC[i]).margin(1e-15));
    CHECK(diff[i] == Approx(wCA[i]).margin(1e-15));
    CHECK(diff[i] == Approx(-(1.5 * a1[i] - 2.0 * b2[i])).margin(1e-15));
  }
  // ^A w^C + ^N w^A (the chain written in reverse) = ^N w^C
  const auto rev = kane::express<N>(kane::angular_velocity<A, C>() + kane::angular_velocity<N, A>(), ev);
  for (int i = 0; i < 3; ++i) CHECK(rev[i] == Approx(wNC[i]).margin(1e-15));
  // update copies the state: a temporary is safe, and a later change of s is not seen until update
  ev.update(state6{s});
  s.q[0] += 0.4;
  CHECK(kane::express<N>(e<A, 1>, ev)[0] == Approx(std::cos(0.3)));
  CHECK(ev.coordinate_value<1, 0>() == 0.3);
  ev.update(s);
  CHECK(kane::express<N>(e<A, 1>, ev)[0] == Approx(std::cos(0.7)));
}

// Components known to be zero at compile time are not formed: q1' n1 + q2' n2 has no n3 part, and
// a x b drops the products with a known zero. An inf in q1' stays in its component (inf * 0 would
// make NaN of the others) and -0 keeps its sign (x + 0 would not).
TEST_CASE("kinematics: components known to be zero take no arithmetic") {
  constexpr auto v = kane::dt(q1{}) * e<N, 1> + kane::dt(q2{}) * e<N, 2>;
  using kane::detail::entry;
  using p3 = kane::detail::pattern3;
  constexpr entry z = entry::zero, o = entry::other;
  static_assert(kane::detail::zeros_in_v<void, decltype(v)> == p3{o, o, z});
  static_assert(kane::detail::zeros_in_v<A, decltype(kane::dt(q1{}) * e<A, 1>)> == p3{o, z, z});
  static_assert(kane::detail::zeros_in_v<A, decltype(kane::dt(q1{}) * e<N, 1>)> ==
                p3{o, o, o});                                                         // N's axes in A
  static_assert(kane::detail::cross_zeros(p3{o, z, z}, p3{z, o, z}) == p3{z, z, o});  // e1 x e2 = e3
  static_assert(kane::detail::cross_zeros(p3{o, z, z}, p3{o, z, z}) == p3{z, z, z});  // e1 x e1 = 0
  state6 s;
  s.qd = {std::numeric_limits<double>::infinity(), -0.0, 0.5, 0, 0, 0};
  kane::evaluator<state6, kane::frames<A>> ev;
  ev.update(s);
  const auto x = kane::express<N>(v, ev);
  CHECK(std::isinf(x[0]));
  CHECK((x[1] == 0.0 && std::signbit(x[1])));
  CHECK((x[2] == 0.0 && !std::isnan(x[2])));
  const auto w = kane::express<N>(kane::cross(kane::dt(q3{}) * e<N, 1>, kane::dt(q1{}) * e<N, 2>), ev);
  CHECK(w[0] == 0.0);  // inf would make NaN of 0.5 * 0 * inf
  CHECK(w[1] == 0.0);
  CHECK(std::isinf(w[2]));
}
