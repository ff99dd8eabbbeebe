// Rotations by angles that are not bare coordinates (frames/angle.hpp): q + c,
// a parameter, a constant, and 2 q3 - q4 about a non-principal axis. Direction
// cosines against products of Eigen's AngleAxis, angular velocities and
// accelerations against finite differences of direction cosines, point
// velocities against finite differences of positions, partial angular
// velocities against d(theta)/dq_r k.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include <kane/kane.hpp>

namespace {
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;
struct lam : kane::parameter<1> {};
struct len : kane::parameter<2> {};
inline constexpr len L;

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::angle<kane::q<1> + literal(0.3)>>> {};
struct Aq : kane::frame<N, kane::simple<kane::axis::z, q<2>>> {};  // A at q2 = q1 + 0.3
struct H : kane::frame<A, kane::simple<kane::axis::y, lam>> {};    // a parameter, like a head-tube angle
struct K : kane::frame<H, kane::simple<kane::axis::x, kane::constant<1, 2>>> {};
using k_axis = kane::direction<1, 2, 2>;
struct B : kane::frame<K, kane::simple<k_axis, kane::angle<2.0 * kane::q<3> - kane::q<4>>>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, L * e<B, 1> + 0.2 * e<H, 3> + kane::q<4> * e<K, 2>> {};

using St = kane::state<double, 4, 4, 2>;
using Ev = kane::evaluator<St, kane::frames<B, Aq>>;
constexpr double lambda = 0.35, length = 0.9;

St random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-2, 2);
  St s;
  for (std::size_t i = 0; i < 4; ++i) s.q[i] = d(rng), s.qd[i] = d(rng), s.qdd[i] = d(rng);
  s.p = {lambda, length};
  return s;
}
St at_time(const St& s, double h) {
  St r = s;
  for (std::size_t i = 0; i < 4; ++i) {
    r.q[i] = s.q[i] + s.qd[i] * h + s.qdd[i] * h * h / 2;
    r.qd[i] = s.qd[i] + s.qdd[i] * h;
  }
  return r;
}
// ^N P^B: row i is b_i in N; b_i = R_z(q1 + 0.3) R_y(lambda) R_x(1/2) R_k(2 q3 - q4) n_i.
Eigen::Matrix3d expected_NB(const St& s) {
  const Eigen::Vector3d k = Eigen::Vector3d(1, 2, 2) / 3;
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(s.q[0] + 0.3, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(lambda, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(2 * s.q[2] - s.q[3], k))
          .toRotationMatrix();
  return r.transpose();
}
Eigen::Vector3d in_N(const auto& x, const St& s) {
  Ev ev;
  ev.update(s);
  return kane::express<N>(x, ev).eigen();
}
}  // namespace

TEST_CASE("angle: direction cosines of q + c, a parameter, a constant and 2 q3 - q4") {
  std::mt19937 rng(41);
  for (int n = 0; n < 20; ++n) {
    St s = random_state(rng);
    s.q[1] = s.q[0] + 0.3;
    CHECK((kane::direction_cosines<N, B>(s).eigen() - expected_NB(s)).norm() < 1e-14);
    // an angle's sin and cos by std::sin and std::cos, a coordinate's by kane's kernel: an ulp or two apart
    CHECK((kane::direction_cosines<N, A>(s).eigen() - kane::direction_cosines<N, Aq>(s).eigen()).norm() <
          1e-15);
    Ev ev;
    ev.update(s);
    CHECK((ev.axes<B>().transpose() - expected_NB(s)).norm() < 1e-14);
    // the tree's symbolic direction cosines: e_N1 . e_A1 = cos(q1 + 0.3), e_A3 . e_H1 = -sin(lambda)
    CHECK(kane::evaluate(kane::dot(e<N, 1>, e<A, 1>), ev) == Approx(std::cos(s.q[0] + 0.3)).margin(1e-15));
    CHECK(kane::evaluate(kane::dot(e<A, 3>, e<H, 1>), ev) == Approx(-std::sin(lambda)).margin(1e-15));
    CHECK(kane::evaluate(kane::dt(kane::dot(e<N, 1>, e<A, 1>)), ev) ==
          Approx(-std::sin(s.q[0] + 0.3) * s.qd[0]).margin(1e-14));
  }
}

TEST_CASE("angle: angular velocity and acceleration follow from the angle's derivatives") {
  std::mt19937 rng(43);
  const double h = 1e-5;
  const Eigen::Vector3d k = Eigen::Vector3d(1, 2, 2) / 3;
  for (int n = 0; n < 20; ++n) {
    const St s = random_state(rng), sp = at_time(s, h), sm = at_time(s, -h);
    // eq. (8) with finite differences of ^N P^B: w = b1 (b2' . b3) + b2 (b3' . b1) + b3 (b1' . b2)
    const Eigen::Matrix3d M = expected_NB(s), dM = (expected_NB(sp) - expected_NB(sm)) / (2 * h);
    const Eigen::Vector3d w_B(dM.row(1).dot(M.row(2)), dM.row(2).dot(M.row(0)), dM.row(0).dot(M.row(1)));
    const Eigen::Vector3d w = in_N(kane::angular_velocity<N, B>(), s);
    CHECK((w - M.transpose() * w_B).norm() < 1e-8);
    // closed form: q1' n3 + (2 q3' - q4') k with k in N
    const Eigen::Vector3d kN = M.transpose() * k;  // k has the same components in K and B
    CHECK((w - (s.qd[0] * Eigen::Vector3d::UnitZ() + (2 * s.qd[2] - s.qd[3]) * kN)).norm() < 1e-13);
    // the constant and parameter edges turn nothing
    CHECK(in_N(kane::angular_velocity<A, K>(), s).norm() == 0);
    const Eigen::Vector3d alpha = in_N(kane::angular_acceleration<N, B>(), s);
    const Eigen::Vector3d dw =
        (in_N(kane::angular_velocity<N, B>(), sp) - in_N(kane::angular_velocity<N, B>(), sm)) / (2 * h);
    CHECK((alpha - dw).norm() < 1e-8);
    // a point through all four edges
    const auto r = kane::position<O, P>();
    const Eigen::Vector3d v = in_N(kane::velocity<N, P>(), s), a = in_N(kane::acceleration<N, P>(), s);
    const Eigen::Vector3d r0 = in_N(r, s), rp = in_N(r, sp), rm = in_N(r, sm);
    CHECK((v - (rp - rm) / (2 * h)).norm() < 1e-8);
    CHECK((a - (rp - 2 * r0 + rm) / (h * h)).norm() < 1e-4);
  }
}

TEST_CASE("angle: partial angular velocities are d(theta)/dq_r k") {
  using Sp = kane::qdot_speeds<4>;
  constexpr auto w = kane::angular_velocity<N, B>();
  using Es = kane::evaluator<kane::state<double, 4, 4, 2>, kane::frames<B>, kane::level::velocity, Sp>;
  std::mt19937 rng(47);
  for (int n = 0; n < 5; ++n) {
    const St r = random_state(rng);
    kane::state<double, 4, 4, 2> s;
    s.q = r.q, s.u = r.qd, s.p = r.p;
    Es ev;
    ev.update(s);
    REQUIRE(ev.status() == kane::solve_status::ok);
    const Eigen::Vector3d kN = expected_NB(r).transpose() * Eigen::Vector3d(1, 2, 2) / 3;
    const auto W = kane::partial_velocities<N>(w, ev);
    CHECK((W.col(0) - Eigen::Vector3d::UnitZ()).norm() < 1e-15);
    CHECK(W.col(1).norm() == 0);  // q2 turns no frame on the path to B
    CHECK((W.col(2) - 2 * kN).norm() < 1e-14);
    CHECK((W.col(3) + kN).norm() < 1e-14);
  }
  // the parameter and constant edges hold no rate: d(^A w^K)/du_r is the zero vector by type
  static_assert(kane::is_zero_vector_v<decltype(kane::partial_velocity<Sp>(kane::angular_velocity<A, K>(),
                                                                           kane::u<1>))>);
}
