// Attitudes supplied at run time (kane::attitude): the free body of
// tests/data/gen_quaternion.py with its attitude read from the state's parameters
// (a unit quaternion or a rotation matrix) and body rates as free speeds, against
// SymPy's numbers; parent rates against body rates; the status of inputs that are
// not rotations.
#include <catch2/catch.hpp>
#include <cmath>

#include <kane/kane.hpp>

#include "data/sympy_quaternion.hpp"

namespace {
using kane::e;
using sympy_quaternion::body;
template <std::size_t I>
using u = kane::speed<I>;

// Bo at q1 n1 + q2 n2 + q3 n3 with u1..u3 = q'; body rates u4..u6 (SymPy's u1..u3);
// P at a b1 + b b2 + c b3 with a, b, c after the attitude's parameters.
struct N : kane::root_frame {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::q<1> * e<N, 1> + kane::q<2> * e<N, 2> + kane::q<3> * e<N, 3>> {};
using speeds = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>), kane::dt(kane::q<3>),
                            kane::free_speed, kane::free_speed, kane::free_speed>;

template <class Source, class Rates, std::size_t NP>
struct body_model {
  struct B : kane::frame<N, kane::attitude<Source, Rates>> {};
  static constexpr kane::parameter<NP - 2> a{};
  static constexpr kane::parameter<NP - 1> b{};
  static constexpr kane::parameter<NP> c{};
  struct P : kane::point<Bo, a * e<B, 1> + b * e<B, 2> + c * e<B, 3>> {};
  using state = kane::state<double, 3, 6, NP>;
  using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::acceleration, speeds>;
};
using by_quaternion = body_model<kane::unit_quaternion<1>, kane::body_rates<u<4>, u<5>, u<6>>, 7>;
using by_matrix = body_model<kane::rotation_matrix<1>, kane::body_rates<u<4>, u<5>, u<6>>, 12>;
using by_parent_rates = body_model<kane::rotation_matrix<1>, kane::parent_rates<u<4>, u<5>, u<6>>, 12>;

// The SymPy case in model M: attitude from the case (quaternion or its matrix), speeds swapped.
template <class M>
typename M::state at(const sympy_quaternion::body_case& x) {
  typename M::state s;
  constexpr std::size_t np = M::state::np;
  for (int i = 0; i < 3; ++i) s.q[i] = x.q[4 + i], s.u[i] = x.u[3 + i], s.ud[i] = x.ud[3 + i];
  for (int i = 0; i < 3; ++i) s.u[3 + i] = x.u[i], s.ud[3 + i] = x.ud[i];
  if constexpr (np == 7)
    for (int i = 0; i < 4; ++i) s.p[i] = x.q[i];
  else
    for (int i = 0; i < 9; ++i) s.p[i] = x.dcm[i];
  for (int i = 0; i < 3; ++i) s.p[np - 3 + i] = x.p[i];
  return s;
}
// |m - x| with x row-major and the speed columns of x swapped (SymPy's u1..u3 are u4..u6 here)
double diff(const Eigen::MatrixXd& m, const double* x, bool swap_columns = false) {
  double d = 0;
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) {
      const int k = swap_columns ? (j + 3) % 6 : j;
      d = std::max(d, std::abs(m(i, j) - x[i * m.cols() + k]));
    }
  return d;
}

template <class M>
void check_against_sympy() {
  using B = typename M::B;
  using P = typename M::P;
  for (const auto& x : body) {
    const auto s = at<M>(x);
    typename M::evaluator ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto w = kane::angular_velocity<N, B>();
    CHECK(diff(ev.template axes<B>().transpose(), x.dcm) < 1e-15);
    CHECK(diff(kane::direction_cosines<N, B>(s).eigen(), x.dcm) < 1e-15);
    CHECK(diff(kane::express<N>(w, ev).eigen().transpose(), x.w_N) < 1e-14);
    CHECK(diff(kane::express<N>(kane::velocity<N, P>(), ev).eigen().transpose(), x.vP_N) < 1e-14);
    CHECK(diff(kane::express<N>(kane::acceleration<N, P>(), ev).eigen().transpose(), x.aP_N) < 1e-13);
    CHECK(diff(kane::partial_velocities<N>(kane::velocity<N, P>(), ev), x.vP_partials, true) < 1e-14);
    CHECK(diff(kane::partial_velocities<N>(w, ev), x.w_partials, true) < 1e-14);
  }
}
}  // namespace

TEST_CASE("attitude: a body whose unit quaternion is read from the state, against SymPy") {
  check_against_sympy<by_quaternion>();
}

TEST_CASE("attitude: a body whose rotation matrix is read from the state, against SymPy") {
  check_against_sympy<by_matrix>();
}

TEST_CASE("attitude: parent rates u = ^N w^B . n_i describe the motion that body rates do") {
  using Bb = by_matrix::B;
  using Bp = by_parent_rates::B;
  for (const auto& x : body) {
    const auto sb = at<by_matrix>(x);
    auto sp = sb;
    // ^N w = M^T ^B w, and ^N w' = M^T ^B w' (alpha is the same derivative in N and in B)
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> m(x.dcm);
    const Eigen::Vector3d wn = m.transpose() * Eigen::Vector3d(sb.u[3], sb.u[4], sb.u[5]);
    const Eigen::Vector3d an = m.transpose() * Eigen::Vector3d(sb.ud[3], sb.ud[4], sb.ud[5]);
    for (int i = 0; i < 3; ++i) sp.u[3 + i] = wn(i), sp.ud[3 + i] = an(i);
    by_matrix::evaluator eb;
    by_parent_rates::evaluator ep;
    eb.update(sb);
    ep.update(sp);
    REQUIRE(ep.status() == kane::solve_status::ok);
    const auto close = [](const auto& p, const auto& q) { return (p.eigen() - q.eigen()).norm() < 1e-13; };
    CHECK(close(kane::express<N>(kane::angular_velocity<N, Bp>(), ep),
                kane::express<N>(kane::angular_velocity<N, Bb>(), eb)));
    CHECK(close(kane::express<N>(kane::angular_acceleration<N, Bp>(), ep),
                kane::express<N>(kane::angular_acceleration<N, Bb>(), eb)));
    CHECK(close(kane::express<N>(kane::acceleration<N, by_parent_rates::P>(), ep),
                kane::express<N>(kane::acceleration<N, by_matrix::P>(), eb)));
    // d(^N w^B)/du_(3+i) = n_i
    const auto pw = kane::partial_velocities<N>(kane::angular_velocity<N, Bp>(), ep);
    CHECK((pw.rightCols<3>() - Eigen::Matrix3d::Identity()).norm() == 0);
  }
}

TEST_CASE("attitude: an input that is not a rotation gives not_a_rotation and NaN") {
  auto s = at<by_matrix>(body[0]);
  by_matrix::evaluator ev;
  const auto w = kane::angular_velocity<N, by_matrix::B>();
  SECTION("within rotation_tolerance: accepted as it is") {
    s.p[0] += 1e-10;
    ev.update(s);
    CHECK(ev.status() == kane::solve_status::ok);
  }
  SECTION("a matrix off by 1e-6") {
    s.p[4] += 1e-6;
    ev.update(s);
    CHECK(ev.status() == kane::solve_status::not_a_rotation);
    CHECK(std::isnan(kane::express<N>(w, ev)[0]));
    CHECK(std::isnan(kane::direction_cosines<N, by_matrix::B>(s)(1, 1)));
  }
  SECTION("a reflection") {
    for (int j = 0; j < 3; ++j) s.p[6 + j] = -s.p[6 + j];  // c3 -> -c3: orthonormal, det -1
    ev.update(s);
    CHECK(ev.status() == kane::solve_status::not_a_rotation);
    CHECK(std::isnan(kane::express<N>(kane::velocity<N, by_matrix::P>(), ev)[2]));
    CHECK(kane::direction_cosines<N, by_matrix::B>(s).eigen().array().isNaN().all());
  }
  SECTION("NaN") {
    s.p[2] = std::nan("");
    ev.update(s);
    CHECK(ev.status() == kane::solve_status::not_finite);
  }
  SECTION("a quaternion of norm 1.01, and one within tolerance") {
    auto sq = at<by_quaternion>(body[1]);
    by_quaternion::evaluator eq;
    for (int i = 0; i < 4; ++i) sq.p[i] *= 1.01;
    eq.update(sq);
    CHECK(eq.status() == kane::solve_status::not_a_rotation);
    CHECK(std::isnan(eq.axes<by_quaternion::B>()(0, 0)));
    CHECK(kane::direction_cosines<by_quaternion::B, N>(sq).eigen().array().isNaN().all());
    for (int i = 0; i < 4; ++i) sq.p[i] = body[1].q[i] * (1 + 1e-12);
    eq.update(sq);
    CHECK(eq.status() == kane::solve_status::ok);
    CHECK(diff(eq.axes<by_quaternion::B>().transpose(), body[1].dcm) < 1e-15);
    CHECK(diff(kane::direction_cosines<N, by_quaternion::B>(sq).eigen(), body[1].dcm) < 1e-15);
  }
}
