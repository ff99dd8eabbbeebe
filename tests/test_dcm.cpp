#include <catch2/catch.hpp>
#include <type_traits>

#include <cmath>
#include <limits>
#include <random>

#include "data/sympy_dcm.hpp"
#include "trees.hpp"

using namespace trees;
using Eigen::Matrix3d;
using kane::direction_cosines;
using kane::vec;

namespace {
template <class L, class R>
concept multipliable = requires(L l, R r) {
  l* r;
};
// ^B P^C . ^A P^B composes and ^A P^B applies to ^A p; other products are rejected by a static
// assertion that names the rule and the frames (compile_fail/dcm_frames).
static_assert(multipliable<kane::dcm<B, C>, kane::dcm<A, B>> && multipliable<kane::dcm<A, B>, vec<A>>);
static_assert(std::is_same_v<decltype(kane::dcm<A, B>().transpose()), kane::dcm<B, A>>);

// Elementary ^P P^C written out: rotation of C from P about x, y, z by q.
Matrix3d Ex(double q) {
  const double c = std::cos(q), s = std::sin(q);
  Matrix3d m;
  m << 1, 0, 0, 0, c, s, 0, -s, c;
  return m;
}
Matrix3d Ey(double q) {
  const double c = std::cos(q), s = std::sin(q);
  Matrix3d m;
  m << c, 0, -s, 0, 1, 0, s, 0, c;
  return m;
}
Matrix3d Ez(double q) {
  const double c = std::cos(q), s = std::sin(q);
  Matrix3d m;
  m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}
Matrix3d elem(int axis, double q) { return axis == 1 ? Ex(q) : axis == 2 ? Ey(q) : Ez(q); }

Matrix3d from9(const double (&m)[9]) {
  Matrix3d r;
  r << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  return r;
}

template <class P>
double max_diff(const P& p, const Matrix3d& m) {
  return (p.eigen() - m).cwiseAbs().maxCoeff();
}

template <class X, class Y>
void check_rotation(const state6& s) {
  const auto p = direction_cosines<X, Y>(s);
  INFO("orthonormality error "
       << (p.eigen() * p.eigen().transpose() - Matrix3d::Identity()).cwiseAbs().maxCoeff());
  CHECK(p.is_rotation(1e-13));
  CHECK(std::abs(p.eigen().determinant() - 1.0) < 1e-13);
}

template <class X, class... Ys>
void check_all_from(const state6& s) {
  (check_rotation<X, Ys>(s), ...);
}
}  // namespace

TEST_CASE("dcm: a simple rotation about z, x, y is the written-out elementary matrix") {
  state6 s;
  s.q = {0.7, -1.9, 2.4, 0.3, 0.0, 0.0};
  CHECK(max_diff(direction_cosines<N, A>(s), Ez(0.7)) < 1e-15);
  CHECK(max_diff(direction_cosines<A, B>(s), Ex(-1.9)) < 1e-15);
  CHECK(max_diff(direction_cosines<B, C>(s), Ey(2.4)) < 1e-15);
  // Row i of ^N P^A is a_i in N: a1 = cos q1 n1 + sin q1 n2.
  const auto a1 = kane::express<N>(vec<A>::e1(), s);
  CHECK(kane::is_approx(a1, vec<N>(std::cos(0.7), std::sin(0.7), 0.0), 1e-15));
}

TEST_CASE("dcm: the chain N -> A -> B -> C is the product of elementary matrices") {
  std::mt19937 rng(7);
  for (int k = 0; k < 200; ++k) {
    const state6 s = random_state(rng);
    const double q1 = s.q[0], q2 = s.q[1], q3 = s.q[2];
    CHECK(max_diff(direction_cosines<N, C>(s), Ey(q3) * Ex(q2) * Ez(q1)) < 1e-14);
    CHECK(max_diff(direction_cosines<C, N>(s), (Ey(q3) * Ex(q2) * Ez(q1)).transpose()) < 1e-14);
    CHECK(max_diff(direction_cosines<A, C>(s), Ey(q3) * Ex(q2)) < 1e-14);
    CHECK(max_diff(direction_cosines<C, A>(s), (Ey(q3) * Ex(q2)).transpose()) < 1e-14);
    // Across branches: ^C P^E = ^N P^E . ^C P^N.
    const Matrix3d NPD =
        Matrix3d(Eigen::AngleAxisd(s.q[3], Eigen::Vector3d(1, 2, 2) / 3).toRotationMatrix()).transpose();
    const Matrix3d DPE = Ez(s.q[0]) * Ex(s.q[5]) * Ez(s.q[4]);
    CHECK(max_diff(direction_cosines<C, E>(s), DPE * NPD * (Ey(q3) * Ex(q2) * Ez(q1)).transpose()) < 1e-14);
  }
}

TEST_CASE("dcm: SymPy's numbers for the chain and a constant axis") {
  state6 s;
  s.q = {0.5, -0.3, 1.2, 0.8, 0.0, 0.0};
  CHECK(max_diff(direction_cosines<N, C>(s), from9(sympy_ref::chain_NC)) < 1e-15);
  CHECK(max_diff(direction_cosines<A, C>(s), from9(sympy_ref::chain_AC)) < 1e-15);
  CHECK(max_diff(direction_cosines<N, D>(s), from9(sympy_ref::axis_122_q08)) < 1e-15);
}

TEST_CASE("dcm: orthonormal with determinant +1 for every pair over random states") {
  std::mt19937 rng(11);
  for (int k = 0; k < 300; ++k) {
    const state6 s = random_state(rng, k < 250 ? 3.2 : 1e4);
    check_all_from<N, N, A, B, C, D, E, F>(s);
    check_all_from<A, N, A, B, C, D, E, F>(s);
    check_all_from<C, N, A, B, C, D, E, F>(s);
    check_all_from<E, N, A, B, C, D, E, F>(s);
    check_all_from<F, N, A, B, C, D, E, F>(s);
    check_all_from<M, M, G>(s);
  }
}

TEST_CASE("dcm: round trips, composition and transpose over random states") {
  std::mt19937 rng(13);
  for (int k = 0; k < 200; ++k) {
    const state6 s = random_state(rng);
    const vec<E> p(0.3 * k, -1.0, 2.0 - 0.01 * k);
    CHECK(kane::is_approx(kane::express<E>(kane::express<B>(p, s), s), p, 1e-13));
    CHECK(kane::is_approx(kane::express<E>(kane::express<F>(p, s), s), p, 1e-13));
    const auto composed = direction_cosines<C, E>(s) * direction_cosines<A, C>(s);
    CHECK(max_diff(composed, direction_cosines<A, E>(s).eigen()) < 1e-14);
    CHECK(max_diff(direction_cosines<F, D>(s).transpose(), direction_cosines<D, F>(s).eigen()) < 1e-15);
    CHECK(max_diff(direction_cosines<C, C>(s), Matrix3d::Identity()) == 0.0);
  }
}

TEST_CASE("dcm: eq. (4) by dot products equals eq. (5)") {
  std::mt19937 rng(17);
  for (int k = 0; k < 200; ++k) {
    const state6 s = random_state(rng);
    const vec<A> pA(1.5, -0.5 * k, 0.25);
    const vec<F> pF = kane::express<F>(pA, s);  // eq. (5): ^F p = ^A P^F . ^A p
    const vec<A> f[3] = {kane::express<A>(vec<F>::e1(), s), kane::express<A>(vec<F>::e2(), s),
                         kane::express<A>(vec<F>::e3(), s)};
    for (int i = 0; i < 3; ++i) CHECK(pF[i] == Approx(kane::dot(f[i], pA)).margin(1e-12));  // b_i = e_Fi . p
  }
}

TEST_CASE("dcm: body-fixed 3-2-1 and 1-2-3 against closed forms") {
  struct B321 : kane::frame<N, kane::body_fixed<3, 2, 1, q1, q2, q3>> {};
  struct B123 : kane::frame<N, kane::body_fixed<1, 2, 3, q1, q2, q3>> {};
  std::mt19937 rng(19);
  for (int k = 0; k < 100; ++k) {
    const state6 s = random_state(rng);
    const double c1 = std::cos(s.q[0]), s1 = std::sin(s.q[0]), c2 = std::cos(s.q[1]), s2 = std::sin(s.q[1]),
                 c3 = std::cos(s.q[2]), s3 = std::sin(s.q[2]);
    // Yaw q1, pitch q2, roll q3: rows are b1, b2, b3 in N.
    Matrix3d m321;
    m321 << c2 * c1, c2 * s1, -s2,                                //
        s3 * s2 * c1 - c3 * s1, s3 * s2 * s1 + c3 * c1, s3 * c2,  //
        c3 * s2 * c1 + s3 * s1, c3 * s2 * s1 - s3 * c1, c3 * c2;
    CHECK(max_diff(direction_cosines<N, B321>(s), m321) < 1e-14);
    Matrix3d m123;
    m123 << c2 * c3, s1 * s2 * c3 + c1 * s3, -c1 * s2 * c3 + s1 * s3,  //
        -c2 * s3, -s1 * s2 * s3 + c1 * c3, c1 * s2 * s3 + s1 * c3,     //
        s2, -s1 * c2, c1 * c2;
    CHECK(max_diff(direction_cosines<N, B123>(s), m123) < 1e-14);
  }
}

namespace {
template <int Body, int I, int J, int K>
void check_sequence_case(const sympy_ref::sequence_case& c) {
  if (c.body != Body || c.i != I || c.j != J || c.k != K) return;
  using O = std::conditional_t<Body == 1, kane::body_fixed<I, J, K, q1, q2, q3>,
                               kane::space_fixed<I, J, K, q1, q2, q3>>;
  struct X : kane::frame<N, O> {};
  state6 s;
  s.q = {c.q[0], c.q[1], c.q[2], 0, 0, 0};
  INFO((Body ? "body" : "space") << "-fixed " << I << "-" << J << "-" << K);
  CHECK(max_diff(direction_cosines<N, X>(s), from9(c.m)) < 1e-14);
  Matrix3d written = Body ? elem(K, c.q[2]) * elem(J, c.q[1]) * elem(I, c.q[0])
                          : elem(I, c.q[0]) * elem(J, c.q[1]) * elem(K, c.q[2]);
  CHECK(max_diff(direction_cosines<N, X>(s), written) < 1e-14);
}
template <int Body>
void check_sequences(const sympy_ref::sequence_case& c) {
  check_sequence_case<Body, 1, 2, 3>(c), check_sequence_case<Body, 1, 3, 2>(c);
  check_sequence_case<Body, 2, 1, 3>(c), check_sequence_case<Body, 2, 3, 1>(c);
  check_sequence_case<Body, 3, 1, 2>(c), check_sequence_case<Body, 3, 2, 1>(c);
  check_sequence_case<Body, 1, 2, 1>(c), check_sequence_case<Body, 1, 3, 1>(c);
  check_sequence_case<Body, 2, 1, 2>(c), check_sequence_case<Body, 2, 3, 2>(c);
  check_sequence_case<Body, 3, 1, 3>(c), check_sequence_case<Body, 3, 2, 3>(c);
}
}  // namespace

TEST_CASE("dcm: all twelve body-fixed and twelve space-fixed sequences against SymPy") {
  int cases = 0;
  for (const auto& c : sympy_ref::sequences) {
    check_sequences<0>(c);
    check_sequences<1>(c);
    ++cases;
  }
  CHECK(cases == 2 * 12 * 3);
}

namespace {
struct tilted {
  static constexpr double components[3] = {3.0, 0.0, 4.0};  // not unit: normalised to (0.6, 0, 0.8)
};
}  // namespace

TEST_CASE("dcm: a constant axis is normalised at compile time") {
  struct T : kane::frame<N, kane::simple<tilted, q1>> {};
  struct U : kane::frame<N, kane::simple<kane::direction<3, 0, 4>, q1>> {};
  constexpr auto k = kane::detail::unit_axis<tilted>::value;
  static_assert(k[0] == 0.6 && k[1] == 0.0 && k[2] == 0.8);
  static_assert(kane::detail::unit_axis<kane::direction<0, 0, 7>>::principal == 2);
  state6 s;
  s.q[0] = 1.1;
  const Matrix3d expected =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.6, 0, 0.8)).toRotationMatrix().transpose();
  CHECK(max_diff(direction_cosines<N, T>(s), expected) < 1e-15);
  CHECK(max_diff(direction_cosines<N, U>(s), expected) < 1e-15);
  // The axis is fixed in both frames: its components in T equal those in N.
  CHECK(kane::is_approx(kane::express<T>(vec<N>(0.6, 0, 0.8), s), vec<T>(0.6, 0, 0.8), 1e-15));
}

TEST_CASE("dcm: NaN and infinite angles give NaN entries, never a trap") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf}) {
    state6 s;
    s.q[0] = bad;
    const auto NPA = direction_cosines<N, A>(s);
    // Entries built from sin q1, cos q1 are NaN; the n3 row and column stay exact.
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) CHECK(std::isnan(NPA(i, j)));
    CHECK(NPA(2, 2) == 1.0);
    CHECK(NPA(0, 2) == 0.0);
    const vec<A> pA = kane::express<A>(vec<N>(1.0, 2.0, 3.0), s);
    CHECK(std::isnan(pA[0]));
    CHECK(std::isnan(pA[1]));
    CHECK(pA[2] == 3.0);
    // Once mixed by a later rotation, every component is NaN.
    const vec<C> pC = kane::express<C>(vec<N>(1.0, 2.0, 3.0), s);
    CHECK((std::isnan(pC[0]) && std::isnan(pC[1]) && std::isnan(pC[2])));
    CHECK_FALSE(NPA.is_rotation(1e-9));
  }
}

TEST_CASE("dcm: is_rotation rejects non-orthonormal and improper matrices") {
  CHECK(kane::dcm<N, A>().is_rotation(0.0));
  Matrix3d m = Ez(0.4);
  CHECK(kane::dcm<N, A>(m).is_rotation(1e-15));
  m(0, 0) *= 1.001;
  CHECK_FALSE(kane::dcm<N, A>(m).is_rotation(1e-6));
  CHECK(kane::dcm<N, A>(m).is_rotation(1e-2));
  const Matrix3d reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
  CHECK_FALSE(kane::dcm<N, A>(reflection).is_rotation(1e-6));
}

TEST_CASE("dcm: float evaluation agrees with double") {
  kane::state<float, 6> sf;
  state6 sd;
  sf.q = {0.5f, -0.3f, 1.2f, 0.8f, 2.0f, -2.5f};
  for (int i = 0; i < 6; ++i) sd.q[i] = double(sf.q[i]);
  const auto pf = direction_cosines<N, F>(sf);
  static_assert(std::is_same_v<decltype(pf), const kane::dcm<N, F, float>>);
  CHECK((pf.eigen().cast<double>() - direction_cosines<N, F>(sd).eigen()).cwiseAbs().maxCoeff() < 1e-5);
}

// eigen() of a temporary, const or not, is a copy: a view would outlive it.
TEST_CASE("dcm: eigen() of an rvalue, const or not, is a matrix, not a view") {
  kane::state<double, 3> s;
  s.q = {0.3, -0.2, 0.9};
  using M = kane::dcm<N, C>;
  static_assert(std::is_same_v<decltype(std::declval<const M&&>().eigen()), Eigen::Matrix3d>);
  static_assert(std::is_same_v<decltype(std::declval<M&&>().eigen()), Eigen::Matrix3d>);
  const auto make = [&]() -> const M { return kane::direction_cosines<N, C>(s); };
  const Eigen::Matrix3d m = make().eigen();
  CHECK((m - kane::direction_cosines<N, C>(s).eigen()).cwiseAbs().maxCoeff() == 0);
}
