// Frames that spin by a free speed (kane::spin): the rolling disc twice, once with
// its spin angle as a coordinate q5 (u = q') and once as a frame that spins at the
// free speed u5 with no angle. With u = q' the two describe one motion: w, alpha,
// v and a of the centre, the constraint solution and the nonholonomic partial
// velocities must agree, and the spin axis stays a unit vector known in N.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include <kane/kane.hpp>

namespace {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct r_ : kane::parameter<1> {};
constexpr r_ r;

// yaw q1, lean q2, contact q3 n1 + q4 n2
struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};
struct O : kane::origin<N> {};
struct Contact : kane::point<O, kane::q<3> * e<N, 1> + kane::q<4> * e<N, 2>> {};
struct Centre : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre, -r * e<L, 3>> {};

// the disc: spin angle q5 about l2, or the free speed u5 about l2
struct D : kane::frame<L, kane::simple<kane::axis::y, q<5>>> {};
struct S : kane::frame<L, kane::spin<kane::axis::y, kane::speed<5>>> {};

// An inertia symmetric about its frame's turn holds in the parent (the disc's in D holds in L, not in
// Y: L turns about l1, about which it is not symmetric), but not in a spinning parent (no axes).
using disc_inertia = kane::inertia<D, Centre, kane::literal(1.0), kane::literal(2.0), kane::literal(1.0)>;
static_assert(std::is_same_v<kane::detail::symmetric_lift<disc_inertia>::type::frame, L>);
struct X : kane::frame<S, kane::simple<kane::axis::x, q<6>>> {};
using below_spin = kane::inertia<X, Centre, kane::literal(1.0), kane::literal(2.0), kane::literal(2.0)>;
static_assert(std::is_same_v<kane::detail::symmetric_lift<below_spin>::type::frame, X>);

using speeds_q = kane::qdot_speeds<5>;
using speeds_s = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>), kane::dt(kane::q<3>),
                              kane::dt(kane::q<4>), kane::free_speed>;
using rolling_q = kane::nonholonomic<speeds_q, kane::dependent<3, 4>,
                                     dot(kane::body_point_velocity<N, D, Centre, Below>(), e<N, 1>),
                                     dot(kane::body_point_velocity<N, D, Centre, Below>(), e<N, 2>)>;
using rolling_s = kane::nonholonomic<speeds_s, kane::dependent<3, 4>,
                                     dot(kane::body_point_velocity<N, S, Centre, Below>(), e<N, 1>),
                                     dot(kane::body_point_velocity<N, S, Centre, Below>(), e<N, 2>)>;
using state_q = kane::state<double, 5, 5, 1>;
using state_s = kane::state<double, 4, 5, 1>;
using eval_q = kane::evaluator<state_q, kane::frames<D>, kane::level::acceleration, speeds_q>;
using eval_s = kane::evaluator<state_s, kane::frames<S>, kane::level::acceleration, speeds_s>;

double diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }
}  // namespace

TEST_CASE("spin: a disc spinning at a free speed moves as the disc turned by a coordinate") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> x(-1.5, 1.5);
  for (int k = 0; k < 5; ++k) {
    state_q a;
    state_s b;
    for (int i = 0; i < 4; ++i) b.q[i] = a.q[i] = x(gen);
    a.q[4] = x(gen);  // the spin angle: no number of the other model depends on it
    for (int i = 0; i < 5; ++i) b.u[i] = a.u[i] = x(gen), b.ud[i] = a.ud[i] = x(gen);
    b.p[0] = a.p[0] = 0.4;
    eval_q eq;
    eval_s es;
    eq.update(a);
    es.update(b);
    REQUIRE(eq.status() == kane::solve_status::ok);
    REQUIRE(es.status() == kane::solve_status::ok);
    const auto wq = kane::angular_velocity<N, D>();
    const auto ws = kane::angular_velocity<N, S>();
    // w = u1 n3 + u2 y1 + u5 l2 and its derivative
    const Eigen::Vector3d w = a.u[0] * Eigen::Vector3d::UnitZ() +
                              a.u[1] * kane::express<N>(e<Y, 1>, eq).eigen() +
                              a.u[4] * kane::express<N>(e<L, 2>, eq).eigen();
    CHECK(diff(kane::express<N>(ws, es).eigen(), w) < 1e-15);
    CHECK(diff(kane::express<N>(wq, eq).eigen(), w) < 1e-15);
    CHECK(diff(kane::express<N>(kane::angular_acceleration<N, S>(), es).eigen(),
               kane::express<N>(kane::angular_acceleration<N, D>(), eq).eigen()) < 1e-14);
    CHECK(diff(kane::express<N>(kane::acceleration<N, Centre>(), es).eigen(),
               kane::express<N>(kane::acceleration<N, Centre>(), eq).eigen()) < 1e-14);
    // the spin axis is a unit vector of S known in N; so is its time derivative in N
    CHECK(diff(kane::express<N>(e<S, 2>, es).eigen(), kane::express<N>(e<D, 2>, eq).eigen()) == 0);
    CHECK(diff(kane::express<N>(kane::dt<N>(e<S, 2>), es).eigen(),
               kane::express<N>(kane::dt<N>(e<D, 2>), eq).eigen()) < 1e-15);
    // partial angular velocities: d w/du5 = l2, and nothing of u5 in the centre's velocity
    const auto pw = kane::partial_velocities<N>(ws, es);
    CHECK(diff(pw, kane::partial_velocities<N>(wq, eq)) < 1e-15);
    CHECK(diff(pw.col(4), kane::express<N>(e<L, 2>, es).eigen()) == 0);
    CHECK(diff(kane::partial_velocities<N>(kane::velocity<N, Centre>(), es),
               kane::partial_velocities<N>(kane::velocity<N, Centre>(), eq)) < 1e-15);
    // rolling: u3, u4 from u1, u2, u5, and the nonholonomic partial velocities
    const auto cq = kane::solve_constraints<rolling_q>(eq);
    const auto cs = kane::solve_constraints<rolling_s>(es);
    REQUIRE(cs.status == kane::solve_status::ok);
    CHECK(diff(cs.A, cq.A) < 1e-15);
    // the contact moves with r u5 y1 = r u5 (cos q1 n1 + sin q1 n2), whatever u1, u2
    CHECK(cs.A(0, 2) == Approx(0.4 * std::cos(b.q[0])).margin(1e-15));
    CHECK(cs.A(1, 2) == Approx(0.4 * std::sin(b.q[0])).margin(1e-15));
    CHECK(cs.A.leftCols<2>().cwiseAbs().maxCoeff() < 1e-15);
    CHECK(diff(kane::nonholonomic_partial_velocities<N, rolling_s>(kane::velocity<N, Centre>(), es, cs),
               kane::nonholonomic_partial_velocities<N, rolling_q>(kane::velocity<N, Centre>(), eq, cq)) <
          1e-15);
    CHECK(diff(kane::nonholonomic_partial_velocities<N, rolling_s>(ws, es, cs),
               kane::nonholonomic_partial_velocities<N, rolling_q>(wq, eq, cq)) < 1e-15);
  }
}

TEST_CASE("spin: a free speed defines no q' and needs no coordinate") {
  static_assert(speeds_s::n == 5 && speeds_s::defined == 4 && speeds_s::rows == 4);
  state_s b;
  b.q = {0.3, -0.2, 1.0, 2.0};
  b.u = {0.1, 0.2, 0.3, 0.4, 7.0};
  b.p[0] = 0.4;
  eval_s es;
  es.update(b);
  REQUIRE(es.status() == kane::solve_status::ok);
  const auto qd = es.coordinate_rates();
  for (int i = 0; i < 4; ++i) CHECK(qd[i] == b.u[i]);
  CHECK(es.W().rows() == 4);
  b.u[4] = std::nan("");  // the spin rate is read and checked like every speed
  es.update(b);
  CHECK(es.status() == kane::solve_status::not_finite);
}

namespace {
// a wheel spinning at u5 about the oblique axis (l1 + 2 l2 + 2 l3) / 3: of its axes only that one is known
struct T : kane::frame<L, kane::spin<kane::direction<1, 2, 2>, kane::speed<5>>> {};
using eval_t = kane::evaluator<state_s, kane::frames<T>, kane::level::velocity, speeds_s>;
}  // namespace

TEST_CASE("spin: the partial angular velocities of a frame spinning about an oblique axis") {
  state_s b;
  b.q = {0.3, -0.2, 1.0, 2.0};
  b.u = {0.1, 0.2, 0.3, 0.4, 7.0};
  b.p[0] = 0.4;
  eval_t ev;
  ev.update(b);
  REQUIRE(ev.status() == kane::solve_status::ok);
  const auto w = kane::angular_velocity<N, T>();
  const Eigen::Matrix<double, 3, 5> pw = kane::partial_velocities<N>(w, ev);
  // ^N w^T = q1' n3 + q2' y1 + u5 k: the columns, and their sum against w itself
  const Eigen::Vector3d k = ev.axes<L>() * Eigen::Vector3d(1, 2, 2) / 3;
  CHECK((pw.col(4) - k).norm() < 1e-15);
  CHECK((pw.col(0) - Eigen::Vector3d(0, 0, 1)).norm() < 1e-15);
  CHECK((pw.col(1) - Eigen::Vector3d(std::cos(0.3), std::sin(0.3), 0)).norm() < 1e-15);
  CHECK(pw.col(2).norm() == 0);
  const Eigen::Map<const Eigen::Matrix<double, 5, 1>> u(b.u.data());
  CHECK((pw * u - kane::express<N>(w, ev).eigen()).norm() < 1e-14);
}
