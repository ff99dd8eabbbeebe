// A free rigid body with Euler parameters (examples/models/free_body.hpp): kinematic
// equations with 7 coordinates and 6 speeds, direction cosines, w, v and a of a point,
// partial velocities against SymPy (tests/data/gen_quaternion.py); the same attitude by
// body-fixed 3-2-1 angles; w against finite differences of direction cosines; the
// normalisation on update and the status of a zero quaternion.
#include <catch2/catch.hpp>
#include <cmath>

#include "../examples/models/free_body.hpp"
#include "data/sympy_quaternion.hpp"

namespace {
using namespace models::free_body;
using sympy_quaternion::body;

state at(const sympy_quaternion::body_case& c) {
  state s;
  for (int i = 0; i < 7; ++i) s.q[i] = c.q[i];
  for (int i = 0; i < 6; ++i) s.u[i] = c.u[i], s.ud[i] = c.ud[i];
  s.p = {c.p[0], c.p[1], c.p[2]};
  return s;
}
double max_diff(const Eigen::MatrixXd& m, const double* x) {  // x row-major
  double d = 0;
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) d = std::max(d, std::abs(m(i, j) - x[i * m.cols() + j]));
  return d;
}

// The same body by body-fixed 3-2-1 angles q1..q3 (yaw, pitch, roll), mass centre q4..q6.
struct B321 : kane::frame<N, kane::body_fixed<3, 2, 1, q<1>, q<2>, q<3>>> {};
struct Bo3 : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2> + kane::q<6> * e<N, 3>> {};
struct P3 : kane::point<Bo3, a * e<B321, 1> + b * e<B321, 2> + c * e<B321, 3>> {};
// The free-body helpers spell the recipe of examples/models/free_body.hpp.
static_assert(std::is_same_v<kane::free_body_speeds<N, B, 5>, models::free_body::speeds>);
static_assert(std::is_same_v<decltype(kane::position_coordinates<N, 5>), decltype(Bo::position)>);
using speeds321 = kane::angular_velocity_speeds<N, B321, B321, kane::dt(kane::q<4>), kane::dt(kane::q<5>),
                                                kane::dt(kane::q<6>)>;
using state321 = kane::state<double, 6, 6, 3>;
using evaluator321 = kane::evaluator<state321, kane::frames<B321>, kane::level::acceleration, speeds321>;
}  // namespace

TEST_CASE("quaternion: kinematic equations, w, v, a and partial velocities against SymPy") {
  for (const auto& c : body) {
    const state s = at(c);
    evaluator ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto qd = ev.coordinate_rates();
    for (int i = 0; i < 7; ++i) CHECK(qd[i] == Approx(c.qd[i]).margin(1e-14));
    CHECK(max_diff(kane::direction_cosines<N, B>(s).eigen(), c.dcm) < 1e-15);
    CHECK(max_diff(ev.axes<B>().transpose(), c.dcm) < 1e-15);
    CHECK(max_diff(kane::express<N>(w, ev).eigen().transpose(), c.w_N) < 1e-14);
    CHECK(max_diff(kane::express<N>(kane::velocity<N, P>(), ev).eigen().transpose(), c.vP_N) < 1e-14);
    CHECK(max_diff(kane::express<N>(kane::acceleration<N, P>(), ev).eigen().transpose(), c.aP_N) < 1e-13);
    CHECK(max_diff(kane::partial_velocities<N>(kane::velocity<N, P>(), ev), c.vP_partials) < 1e-14);
    CHECK(max_diff(kane::partial_velocities<N>(w, ev), c.w_partials) < 1e-14);
    // the norm is kept: q . q' = 0
    double dot = 0;
    for (int i = 0; i < 4; ++i) dot += s.q[i] * qd[i];
    CHECK(std::abs(dot) < 1e-15);
  }
}

TEST_CASE("quaternion: the same attitude and motion described by body-fixed 3-2-1 angles") {
  for (const auto& c : body) {
    const state s = at(c);
    evaluator ev;
    ev.update(s);
    const Eigen::Matrix3d M = kane::direction_cosines<N, B>(s).eigen();  // row i: b_i in N
    state321 s3;
    s3.q = {std::atan2(M(0, 1), M(0, 0)),
            -std::asin(M(0, 2)),
            std::atan2(M(1, 2), M(2, 2)),
            s.q[4],
            s.q[5],
            s.q[6]};
    s3.u = s.u, s3.ud = s.ud, s3.p = s.p;
    evaluator321 ev3;
    ev3.update(s3);
    REQUIRE(ev3.status() == kane::solve_status::ok);
    CHECK((kane::direction_cosines<N, B321>(s3).eigen() - M).norm() < 1e-14);
    CHECK((kane::express<N>(w, ev).eigen() - kane::express<N>(kane::angular_velocity<N, B321>(), ev3).eigen())
              .norm() < 1e-14);
    CHECK((kane::express<N>(kane::angular_acceleration<N, B>(), ev).eigen() -
           kane::express<N>(kane::angular_acceleration<N, B321>(), ev3).eigen())
              .norm() < 1e-13);
    CHECK((kane::express<N>(kane::velocity<N, P>(), ev).eigen() -
           kane::express<N>(kane::velocity<N, P3>(), ev3).eigen())
              .norm() < 1e-14);
    CHECK((kane::express<N>(kane::acceleration<N, P>(), ev).eigen() -
           kane::express<N>(kane::acceleration<N, P3>(), ev3).eigen())
              .norm() < 1e-13);
  }
}

TEST_CASE("quaternion: w from finite differences of direction cosines along the solved q'") {
  const double h = 1e-6;
  for (const auto& c : body) {
    const state s = at(c);
    evaluator ev;
    ev.update(s);
    const auto qd = ev.coordinate_rates();
    state sp = s, sm = s;
    for (int i = 0; i < 7; ++i) sp.q[i] += h * qd[i], sm.q[i] -= h * qd[i];
    const Eigen::Matrix3d M = kane::direction_cosines<N, B>(s).eigen();
    const Eigen::Matrix3d dM =
        (kane::direction_cosines<N, B>(sp).eigen() - kane::direction_cosines<N, B>(sm).eigen()) / (2 * h);
    // eq. (8) in B: w = b1 (b2' . b3) + b2 (b3' . b1) + b3 (b1' . b2)
    const Eigen::Vector3d wB(dM.row(1).dot(M.row(2)), dM.row(2).dot(M.row(0)), dM.row(0).dot(M.row(1)));
    for (int i = 0; i < 3; ++i) CHECK(wB[i] == Approx(c.u[i]).margin(1e-9));
    // eq. (6): d b1/dq2 in N = (dw/dq2') x b1, against a difference of the normalised cosines
    state qp = s, qm = s;
    qp.q[1] += h, qm.q[1] -= h;
    const Eigen::Vector3d db1 =
        (kane::direction_cosines<N, B>(qp).eigen().row(0) - kane::direction_cosines<N, B>(qm).eigen().row(0))
            .transpose() /
        (2 * h);
    CHECK((kane::express<N>(kane::diff<N>(e<B, 1>, kane::q<2>), ev).eigen() - db1).norm() < 1e-8);
  }
}

TEST_CASE(
    "quaternion: Euler parameters are normalised on update; zero, NaN or a norm beyond 2^+-512 gives "
    "not_finite") {
  const auto& c = body[0];
  state s = at(c);
  for (int i = 0; i < 4; ++i) s.q[i] *= 2.5;
  evaluator ev;
  ev.update(s);
  REQUIRE(ev.status() == kane::solve_status::ok);
  for (int i = 0; i < 4; ++i) CHECK(ev.state().q[i] == Approx(c.q[i]).margin(1e-15));
  const auto qd = ev.coordinate_rates();
  for (int i = 0; i < 7; ++i) CHECK(qd[i] == Approx(c.qd[i]).margin(1e-14));
  CHECK(max_diff(kane::express<N>(kane::velocity<N, P>(), ev).eigen().transpose(), c.vP_N) < 1e-14);
  for (const double scale : {1e-150, 1e150}) {  // norms from 2^-512 to 2^512: norm^2 and 1 / norm^2 finite
    state t = at(c);
    for (int i = 0; i < 4; ++i) t.q[i] *= scale;
    ev.update(t);
    REQUIRE(ev.status() == kane::solve_status::ok);
    for (int i = 0; i < 4; ++i) CHECK(ev.state().q[i] == Approx(c.q[i]).margin(1e-15));
  }
  for (const double scale : {1e-160, 1e160}) {  // beyond: not_finite, never q = 0 with ok
    state t = at(c);
    for (int i = 0; i < 4; ++i) t.q[i] *= scale;
    ev.update(t);
    CHECK(ev.status() == kane::solve_status::not_finite);
    CHECK(std::isnan(ev.coordinate_rates()[0]));
  }
  for (double bad : {0.0, std::nan("")}) {
    state z = at(c);
    for (int i = 0; i < 4; ++i) z.q[i] = i == 0 ? bad : 0.0;
    ev.update(z);
    CHECK(ev.status() == kane::solve_status::not_finite);
    CHECK(std::isnan(ev.coordinate_rates()[0]));
    CHECK(std::isnan(kane::express<N>(kane::velocity<N, P>(), ev)[0]));
  }
}

TEST_CASE("quaternion: parent-fixed rates u_i = w . n_i") {
  using speeds_n = kane::speeds<dot(w, e<N, 1>), dot(w, e<N, 2>), dot(w, e<N, 3>), kane::dt(kane::q<5>),
                                kane::dt(kane::q<6>), kane::dt(kane::q<7>), kane::unit_norm<B>>;
  using evaluator_n = kane::evaluator<state, kane::frames<B>, kane::level::acceleration, speeds_n>;
  for (const auto& c : body) {
    // the state of the SymPy case with its angular velocity given by its components in N
    state s = at(c);
    for (int i = 0; i < 3; ++i) s.u[i] = c.w_N[i];
    evaluator_n ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const auto qd = ev.coordinate_rates();
    for (int i = 0; i < 7; ++i) CHECK(qd[i] == Approx(c.qd[i]).margin(1e-14));
    CHECK(max_diff(kane::express<N>(kane::velocity<N, P>(), ev).eigen().transpose(), c.vP_N) < 1e-14);
    // w_r = n_r: the partial angular velocities in N are the identity
    const Eigen::MatrixXd W = kane::partial_velocities<N>(w, ev);
    CHECK((W.leftCols(3) - Eigen::Matrix3d::Identity()).norm() < 1e-14);
    CHECK(W.rightCols(3).norm() == 0);
  }
}
