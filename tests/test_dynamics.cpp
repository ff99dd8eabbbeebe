// Kane's dynamical equations (dynamics/): closed forms first, then SymPy's
// KanesMethod (tests/data/gen_dynamics.py) for a 3D double pendulum of rigid
// links and for a free rigid body.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <kane/kane.hpp>

namespace {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct L_ : kane::parameter<1> {};
struct m_ : kane::parameter<2> {};
struct g_ : kane::parameter<3> {};
constexpr L_ L;
constexpr m_ m;
constexpr g_ g;

// a pendulum: a particle at L below O on a rod turning about n1 by q1
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::x, q<1>>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, -L * e<A, 3>> {};
using pendulum = kane::system<kane::particle<P, m>, kane::gravity<-g * e<N, 3>>>;
using state1 = kane::state<double, 1, 1, 3>;
using eval1 = kane::evaluator<state1, kane::frames<A>, kane::level::acceleration, kane::qdot_speeds<1>>;
}  // namespace

TEST_CASE("dynamics: a pendulum, m L^2 q'' = -m g L sin q") {
  state1 s;
  s.p = {0.7, 2.0, 9.81};
  s.q = {0.4};
  s.u = {1.3};
  s.ud = {5.0};  // any u': M and f do not depend on it
  eval1 ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<pendulum>(ev);
  REQUIRE(eom.status == kane::solve_status::ok);
  CHECK(eom.M(0, 0) == Approx(2.0 * 0.49).epsilon(1e-15));
  CHECK(eom.f(0) == Approx(-2.0 * 9.81 * 0.7 * std::sin(0.4)).epsilon(1e-14));
  const auto [ud, st] = kane::speed_derivatives(eom);
  CHECK(st == kane::solve_status::ok);
  CHECK(ud(0) == Approx(-9.81 / 0.7 * std::sin(0.4)).epsilon(1e-14));
  CHECK(kane::kinetic_energy<pendulum>(ev) == Approx(0.5 * 2.0 * 0.49 * 1.3 * 1.3).epsilon(1e-15));
}

TEST_CASE("dynamics: statuses have names") {
  CHECK(std::string(kane::to_string(kane::solve_status::ok)) == "ok");
  CHECK(std::string(kane::to_string(kane::solve_status::singular)) == "singular");
  CHECK(std::string(kane::to_string(kane::solve_status::not_finite)) == "not_finite");
  CHECK(std::string(kane::to_string(kane::solve_status::not_converged)) == "not_converged");
  CHECK(std::string(kane::to_string(kane::solve_status::not_a_rotation)) == "not_a_rotation");
  CHECK(std::string(kane::to_string(kane::solve_status::wrong_size)) == "wrong_size");
}

TEST_CASE("dynamics: kane::motion with vectors of another run-time size says wrong_size") {
  state1 s;
  s.p = {0.7, 2.0, 9.81};
  kane::motion<pendulum, eval1> f(s);
  // x of 1 or 3 numbers, dx/dt of 1: nothing beyond them is read or written (AddressSanitizer)
  for (const Eigen::Index nx : {1, 2, 3})
    for (const Eigen::Index nd : {1, 2, 3}) {
      const Eigen::VectorXd x = Eigen::VectorXd::Constant(nx, 0.4);
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(nd);
      f(x, dx, 0.0);
      if (nx == 2 && nd == 2) {
        CHECK(f.status() == kane::solve_status::ok);
        CHECK(dx(1) == Approx(-9.81 / 0.7 * std::sin(0.4)).epsilon(1e-14));
      } else {
        CHECK(f.status() == kane::solve_status::wrong_size);
        for (Eigen::Index i = 0; i < std::min<Eigen::Index>(nd, 2); ++i) CHECK(std::isnan(dx(i)));
        if (nd == 3) CHECK(dx(2) == 0.0);
      }
    }
}

TEST_CASE("dynamics: kane::motion over an evaluator without a speed set integrates u = q'") {
  state1 s;
  s.p = {0.7, 2.0, 9.81};
  using bare = kane::evaluator<state1, kane::frames<A>, kane::level::acceleration>;
  kane::motion<pendulum, bare> f(s);
  kane::motion<pendulum, eval1> g(s);
  const std::array<double, 2> x = {0.4, 1.3};
  std::array<double, 2> dx{}, dy{};
  f(x, dx, 0.0);
  g(x, dy, 0.0);
  CHECK(f.status() == kane::solve_status::ok);
  CHECK(dx[0] == 1.3);  // q' = u, not a field never filled
  CHECK(dx[1] == Approx(-9.81 / 0.7 * std::sin(0.4)).epsilon(1e-14));
  CHECK(dy[0] == dx[0]);
  CHECK(dy[1] == Approx(dx[1]).epsilon(1e-15));
}

#include "sympy_states.hpp"

namespace {
// SymPy's 3D double pendulum (examples/models/pendulum3d.hpp), parameters in the order of
// sympy_dynamics::pendulum_p.
namespace pd = models::pendulum3d;

// SymPy's free body with body rates u1..u3 and the mass centre's velocity u4..u6, here by
// Euler parameters (examples/models/free_body.hpp, p1..p3 = a, b, c of the point P where
// the force acts); m, the inertia about Bo in B, g, the torque in B and the force in N after them.
namespace fb {
namespace m = models::free_body;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};
using system = kane::system<
    kane::rigid_body<m::B, m::Bo, p<4>, kane::inertia<m::B, m::Bo, p<5>, p<6>, p<7>, p<8>, p<9>, p<10>>>,
    kane::gravity<-p<11> * e<m::N, 3>>,
    kane::torque<m::B, p<12> * e<m::B, 1> + p<13> * e<m::B, 2> + p<14> * e<m::B, 3>>,
    kane::force<m::P, p<15> * e<m::N, 1> + p<16> * e<m::N, 2> + p<17> * e<m::N, 3>>>;
using state = kane::state<double, 7, 6, 17>;
using evaluator = kane::evaluator<state, kane::frames<m::B>, kane::level::acceleration, m::speeds>;
using B = m::B;
}  // namespace fb
}  // namespace

TEST_CASE("dynamics: a 3D double pendulum with springs, dampers and drag against SymPy's KanesMethod") {
  for (const auto& x : sympy_dynamics::pendulum) {
    pd::state s = sympy_states::pendulum(x);
    s.ud = {0.3, -7.0};
    pd::evaluator ev;
    ev.update(s);
    const auto eom = kane::mass_matrix_and_forcing<pd::system>(ev);
    REQUIRE(eom.status == kane::solve_status::ok);
    for (int i = 0; i < 4; ++i) CHECK(eom.M(i / 2, i % 2) == Approx(x.M[i]).epsilon(1e-13));
    for (int i = 0; i < 2; ++i) CHECK(eom.f(i) == Approx(x.f[i]).epsilon(1e-13));
    const auto [ud, st] = kane::speed_derivatives(eom);
    REQUIRE(st == kane::solve_status::ok);
    for (int i = 0; i < 2; ++i) CHECK(ud(i) == Approx(x.ud[i]).epsilon(1e-13));
    CHECK(kane::kinetic_energy<pd::system>(ev) == Approx(x.T).epsilon(1e-14));
    CHECK(kane::evaluate(pd::potential, ev) == Approx(x.V).epsilon(1e-14));
  }
}

TEST_CASE("dynamics: a free body with Euler parameters, a torque and a force against SymPy's KanesMethod") {
  for (const auto& x : sympy_dynamics::body) {
    const fb::state s = sympy_states::free_body(x);
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> c(x.dcm);
    fb::evaluator ev;
    ev.update(s);
    REQUIRE((ev.axes<fb::B>().transpose() - c).norm() < 1e-14);
    const auto eom = kane::mass_matrix_and_forcing<fb::system>(ev);
    REQUIRE(eom.status == kane::solve_status::ok);
    for (int i = 0; i < 36; ++i) CHECK(eom.M(i / 6, i % 6) == Approx(x.M[i]).margin(1e-14));
    for (int i = 0; i < 6; ++i) CHECK(eom.f(i) == Approx(x.f[i]).margin(1e-13));
    const auto [ud, st] = kane::speed_derivatives(eom);
    for (int i = 0; i < 6; ++i) CHECK(ud(i) == Approx(x.ud[i]).margin(1e-13));
    CHECK(kane::kinetic_energy<fb::system>(ev) == Approx(x.T).epsilon(1e-14));
  }
}

TEST_CASE("dynamics: mass_matrix alone from a pose-level evaluator is SymPy's mass matrix") {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  using pose = kane::evaluator<pd::state, kane::frames<pd::B>, kane::level::pose, kane::qdot_speeds<2>>;
  for (const auto& x : sympy_dynamics::pendulum) {
    pd::state s;
    for (int i = 0; i < 21; ++i) s.p[i] = sympy_dynamics::pendulum_p[i];
    s.q = {x.q[0], x.q[1]};
    s.u = {nan, nan};  // read at no level below velocity
    pose ev;
    ev.update(s);
    const auto mm = kane::mass_matrix<pd::system>(ev);
    REQUIRE(mm.status == kane::solve_status::ok);
    for (int i = 0; i < 4; ++i) CHECK(mm.M(i / 2, i % 2) == Approx(x.M[i]).epsilon(1e-13));
    s.q[1] = nan;
    ev.update(s);
    CHECK(kane::mass_matrix<pd::system>(ev).status == kane::solve_status::not_finite);
  }
  using body_pose =
      kane::evaluator<fb::state, kane::frames<fb::B>, kane::level::pose, models::free_body::speeds>;
  for (const auto& x : sympy_dynamics::body) {
    fb::state s = sympy_states::free_body(x);
    for (double& u : s.u) u = nan;  // read at no level below velocity
    body_pose ev;
    ev.update(s);
    const auto mm = kane::mass_matrix<fb::system>(ev);
    REQUIRE(mm.status == kane::solve_status::ok);
    for (int i = 0; i < 36; ++i) CHECK(mm.M(i / 6, i % 6) == Approx(x.M[i]).margin(1e-14));
  }
}

TEST_CASE("dynamics: the free body obeys Newton's and Euler's equations") {
  for (const auto& x : sympy_dynamics::body) {
    fb::state s;
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> c(x.dcm);
    const Eigen::Quaterniond e(Eigen::Matrix3d(c.transpose()));
    s.q = {e.w(), e.x(), e.y(), e.z(), 0.1, 0.2, 0.3};
    for (int i = 0; i < 6; ++i) s.u[i] = x.u[i];
    s.p = {0.3, -0.2, 0.5, 1.7, 0.8, 0.9, 1.1, 0.05, -0.03, 0.07, 9.81, 0.4, -0.6, 0.2, 1.5, -0.5, 2.5};
    fb::evaluator ev;
    ev.update(s);
    const auto [ud, st] = kane::speed_derivatives(kane::mass_matrix_and_forcing<fb::system>(ev));
    REQUIRE(st == kane::solve_status::ok);
    // I w' + w x I w = t + r x F (in B), m a = F + m g (in N)
    Eigen::Matrix3d i;
    i << 0.8, 0.05, 0.07, 0.05, 0.9, -0.03, 0.07, -0.03, 1.1;
    const Eigen::Vector3d w(s.u[0], s.u[1], s.u[2]), r(0.3, -0.2, 0.5), f_n(1.5, -0.5, 2.5),
        f_b = c * f_n, t(0.4, -0.6, 0.2);
    const Eigen::Vector3d wd = i.inverse() * (t + r.cross(f_b) - w.cross(i * w));
    const Eigen::Vector3d a = f_n / 1.7 - Eigen::Vector3d(0, 0, 9.81);
    for (int k = 0; k < 3; ++k) {
      CHECK(ud(k) == Approx(wd(k)).margin(1e-13));
      CHECK(ud(3 + k) == Approx(a(k)).margin(1e-13));
    }
  }
}

namespace {
// a body A turning about n1 at O, its mass centre off the axis, inertia given about O
struct Ac : kane::point<O, kane::parameter<4>{} * e<A, 1> - kane::constant<1, 2>{} * L * e<A, 3>> {};
template <std::size_t I>
constexpr kane::parameter<I> pp{};
using about_o = kane::inertia<A, O, pp<5>, pp<6>, pp<7>, pp<8>, pp<9>, pp<10>>;
using moved = kane::parallel_axis<about_o, Ac, m>;
using rod = kane::system<kane::rigid_body<A, Ac, m, moved>>;
using state10 = kane::state<double, 1, 1, 10>;
using eval10 = kane::evaluator<state10, kane::frames<A>, kane::level::acceleration, kane::qdot_speeds<1>>;
}  // namespace

TEST_CASE("dynamics: parallel_axis moves an inertia about O to the mass centre") {
  state10 s;
  const double l = 0.8, mass = 2.5, x = 0.3;
  s.p = {l, mass, 9.81, x, 1.1, 1.3, 0.4, 0.05, -0.07, 0.09};
  s.q = {0.6};
  s.u = {0.0};
  eval10 ev;
  ev.update(s);
  const auto c = moved::components;
  const double d1 = x, d3 = -l / 2;
  CHECK(kane::evaluate(std::get<0>(c), ev) == Approx(1.1 - mass * d3 * d3).epsilon(1e-15));
  CHECK(kane::evaluate(std::get<1>(c), ev) == Approx(1.3 - mass * (d3 * d3 + d1 * d1)).epsilon(1e-15));
  CHECK(kane::evaluate(std::get<2>(c), ev) == Approx(0.4 - mass * d1 * d1).epsilon(1e-15));
  CHECK(kane::evaluate(std::get<3>(c), ev) == Approx(0.05).epsilon(1e-15));
  CHECK(kane::evaluate(std::get<4>(c), ev) == Approx(-0.07).epsilon(1e-15));
  CHECK(kane::evaluate(std::get<5>(c), ev) == Approx(0.09 + mass * d3 * d1).epsilon(1e-15));
  // about the fixed axis n1 = a1 through O: M = (I_O)_11
  CHECK(kane::mass_matrix_and_forcing<rod>(ev).M(0, 0) == Approx(1.1).epsilon(1e-14));
}

// The lower link B turns in A about b2 = a2: an inertia symmetric about b2 may be given in A.
template <class F>
using pendulum_with = kane::system<
    kane::rigid_body<
        pd::A, pd::Ao, fb::p<3>,
        kane::inertia<pd::A, pd::Ao, fb::p<6>, fb::p<7>, fb::p<8>, fb::p<9>, fb::p<10>, fb::p<11>>>,
    kane::rigid_body<pd::B, pd::Bo, fb::p<4>, kane::inertia<F, pd::Bo, fb::p<12>, fb::p<13>, fb::p<12>>>,
    kane::particle<pd::Q, fb::p<5>>, kane::gravity<-fb::p<18> * e<pd::N, 3>>>;

TEST_CASE("dynamics: an inertia symmetric about a joint axis, given in the joint's parent frame") {
  static_assert(kane::detail::recursive_form<pendulum_with<pd::A>, pd::evaluator>);
  for (const auto& x : sympy_dynamics::pendulum) {
    pd::state s = sympy_states::pendulum(x);
    pd::evaluator ev;
    ev.update(s);
    const auto in_a = kane::mass_matrix_and_forcing<pendulum_with<pd::A>>(ev);
    const auto in_b = kane::mass_matrix_and_forcing<pendulum_with<pd::B>>(ev);
    REQUIRE(in_a.status == kane::solve_status::ok);
    CHECK((in_a.M - in_b.M).norm() < 1e-14 * in_b.M.norm());
    CHECK((in_a.f - in_b.f).norm() < 1e-14 * in_b.f.norm());
    CHECK(kane::kinetic_energy<pendulum_with<pd::A>>(ev) ==
          Approx(kane::kinetic_energy<pendulum_with<pd::B>>(ev)).epsilon(1e-14));
  }
}

#include "../examples/models/gyrostat.hpp"
#include "../examples/models/heavy_top.hpp"

namespace {
// The gyrostat with B's mass Mass and the wheel's inertia given in F, its axial moment J.
template <auto Mass, class F, auto J>
using gyrostat_with = kane::system<
    kane::rigid_body<models::gyrostat::B, models::gyrostat::Bo, Mass,
                     kane::inertia<models::gyrostat::B, models::gyrostat::Bo, kane::literal(1.2),
                                   kane::literal(1.5), kane::literal(1.9)>>,
    kane::rigid_body<models::gyrostat::W, models::gyrostat::Bo, kane::literal(0.5),
                     kane::inertia<F, models::gyrostat::Bo, kane::literal(0.01), kane::literal(0.01), J>>>;
}  // namespace

// Body rates as speeds (partial angular velocities the frame's unit vectors), sums in the
// body's frame, the Euler-parameter rows solved in closed form: closed forms by hand.
TEST_CASE("dynamics: a heavy top and a gyrostat with body rates against Euler's equations") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> d(-2, 2);
  namespace ht = models::heavy_top;
  kane::motion<ht::system, ht::evaluator> top(ht::state{});
  for (int k = 0; k < 20; ++k) {
    std::array<double, 6> x{}, dx{};
    for (double& v : x) v = d(rng);
    x[1] = 0.4 + 0.1 * k;  // away from the 3-1-3 singularity
    top(x, dx, 0.0);
    REQUIRE(top.status() == kane::solve_status::ok);
    // Euler about O: I1 = 0.02 + m l^2, the gravity torque m g l s2 (c3 c1 - s3 c2)
    const double I1 = 0.02 + 1.5 * 0.09, I3 = 0.035, h = 1.5 * 9.81 * 0.3 / I1;
    // the evaluator at this call's state: T = (I1 (u1^2 + u2^2) + I3 u3^2) / 2 about O
    const auto ev = top.evaluator();
    CHECK(ev.state().q[1] == x[1]);
    CHECK(kane::kinetic_energy<ht::system>(ev) ==
          Approx((I1 * (x[3] * x[3] + x[4] * x[4]) + I3 * x[5] * x[5]) / 2).margin(1e-13));
    const double s2 = std::sin(x[1]), c2 = std::cos(x[1]), s3 = std::sin(x[2]), c3 = std::cos(x[2]);
    const double q1d = (s3 * x[3] + c3 * x[4]) / s2;
    CHECK(dx[0] == Approx(q1d).margin(1e-12));
    CHECK(dx[1] == Approx(c3 * x[3] - s3 * x[4]).margin(1e-12));
    CHECK(dx[2] == Approx(x[5] - c2 * q1d).margin(1e-12));
    CHECK(dx[3] == Approx((I1 - I3) / I1 * x[4] * x[5] + h * s2 * c3).margin(1e-12));
    CHECK(dx[4] == Approx(-(I1 - I3) / I1 * x[3] * x[5] - h * s2 * s3).margin(1e-12));
    CHECK(dx[5] == Approx(0).margin(1e-12));
  }
  namespace gs = models::gyrostat;
  kane::motion<gs::system, gs::evaluator> body(gs::state{});
  // the wheel's inertia given in the spinning wheel's own frame: symmetric about w3, the same dyadic
  using in_wheel = gyrostat_with<kane::literal(10), gs::W, kane::literal(0.02)>;
  kane::motion<in_wheel, gs::evaluator> body_w(gs::state{});
  for (int k = 0; k < 20; ++k) {
    std::array<double, 14> x{}, dx{}, dw{};
    for (double& v : x) v = d(rng);
    const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    for (int i = 0; i < 4; ++i) x[std::size_t(i)] /= n;
    body(x, dx, 0.0);
    REQUIRE(body.status() == kane::solve_status::ok);
    body_w(x, dw, 0.0);
    for (std::size_t i = 0; i < 14; ++i) CHECK(dw[i] == Approx(dx[i]).margin(1e-14));
    // q' = E(q) w / 2; the gyrostat I w' + w x (I w + J u7 b3) = 0, J (w3 + u7)' = 0
    const double J = 0.02, I1 = 1.21, I2 = 1.51, I3 = 1.92, w1 = x[7], w2 = x[8], w3 = x[9], u7 = x[13];
    const double e0 = x[0], e1 = x[1], e2 = x[2], e3 = x[3];
    CHECK(dx[0] == Approx(0.5 * (-e1 * w1 - e2 * w2 - e3 * w3)).margin(1e-12));
    CHECK(dx[1] == Approx(0.5 * (e0 * w1 - e3 * w2 + e2 * w3)).margin(1e-12));
    CHECK(dx[2] == Approx(0.5 * (e3 * w1 + e0 * w2 - e1 * w3)).margin(1e-12));
    CHECK(dx[3] == Approx(0.5 * (-e2 * w1 + e1 * w2 + e0 * w3)).margin(1e-12));
    for (int i = 4; i < 7; ++i) CHECK(dx[std::size_t(i)] == x[std::size_t(i + 6)]);
    const double w3d = (I1 - I2) / (I3 - J) * w1 * w2;
    CHECK(dx[7] == Approx(-w2 * ((I3 - I2) * w3 + J * u7) / I1).margin(1e-12));
    CHECK(dx[8] == Approx(w1 * ((I3 - I1) * w3 + J * u7) / I2).margin(1e-12));
    CHECK(dx[9] == Approx(w3d).margin(1e-12));
    for (int i = 10; i < 13; ++i) CHECK(dx[std::size_t(i)] == Approx(0).margin(1e-12));
    CHECK(dx[13] == Approx(-w3d).margin(1e-12));
  }
}

// The gyrostat's and the top's M are known at compile time (known_mass_matrix.hpp); with B's
// mass a parameter the gyrostat's is not, and Kane's sums evaluate M: the two agree, and so do u' by the
// known M^-1 and by a Cholesky factorization. A speed that moves no mass is singular.
TEST_CASE("dynamics: an M known at compile time, against the M of Kane's sums") {
  namespace gs = models::gyrostat;
  using summed_system = gyrostat_with<kane::parameter<1>{}, gs::B, kane::literal(0.02)>;
  using summed_state = kane::state<double, 7, 7, 1>;
  using summed_evaluator =
      kane::evaluator<summed_state, kane::frames<gs::W>, kane::level::acceleration, gs::speeds>;
  constexpr auto known = kane::detail::known_mass_matrix<gs::system, gs::N, gs::speeds>;
  STATIC_REQUIRE(known.known);
  STATIC_REQUIRE(!kane::detail::known_mass_matrix<summed_system, gs::N, gs::speeds>.known);
  // the top on body rates: its mass centre's partial velocities l c3 x c_r are constant in C
  constexpr auto top = kane::detail::known_mass_matrix<models::heavy_top::system, models::heavy_top::N,
                                                       models::heavy_top::speeds>;
  STATIC_REQUIRE(top.known);
  const std::array<double, 9> top_m{0.02 + 1.5 * 0.09, 0, 0, 0, 0.02 + 1.5 * 0.09, 0, 0, 0, 0.035};
  for (std::size_t i = 0; i < 9; ++i) CHECK(top.m[i] == Approx(top_m[i]).margin(1e-15));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-2, 2);
  gs::evaluator ev;
  gs::state s{};
  summed_evaluator ev_p;
  summed_state s_p{};
  for (std::size_t i = 0; i < 7; ++i) s_p.q[i] = s.q[i] = d(rng), s_p.u[i] = s.u[i] = d(rng);
  s_p.p[0] = 10;
  ev.update(s);
  ev_p.update(s_p);
  const auto summed = kane::mass_matrix<summed_system>(ev_p);
  REQUIRE(summed.status == kane::solve_status::ok);
  for (int r = 0; r < 7; ++r)
    for (int c = 0; c < 7; ++c)
      CHECK(known.m[std::size_t(r * 7 + c)] == Approx(summed.M(r, c)).margin(1e-14));
  CHECK(known.m[2 * 7 + 6] == 0.02);
  const auto e = kane::mass_matrix_and_forcing<summed_system>(ev_p);
  const auto [ud, status] = kane::forward_dynamics<gs::system>(ev);
  REQUIRE(status == kane::solve_status::ok);
  const Eigen::Matrix<double, 7, 1> ref = e.M.llt().solve(e.f);
  for (int r = 0; r < 7; ++r) CHECK(ud(r) == Approx(ref(r)).margin(1e-13));
  // the wheel without axial inertia: u7 moves no mass
  using massless_spin = gyrostat_with<kane::literal(10), gs::B, kane::literal(0)>;
  STATIC_REQUIRE(kane::detail::known_mass_matrix<massless_spin, gs::N, gs::speeds>.known);
  STATIC_REQUIRE(!kane::detail::known_inverse<massless_spin, gs::N, gs::speeds>.known);
  kane::motion<massless_spin, gs::evaluator> rhs(s);
  std::array<double, 14> x{}, dx{};
  x[0] = 1;
  rhs(x, dx, 0.0);
  CHECK(rhs.status() == kane::solve_status::singular);
  for (double v : dx) CHECK(std::isnan(v));
  // a state that is not finite
  kane::motion<gs::system, gs::evaluator> body(s);
  x[8] = std::numeric_limits<double>::infinity();
  body(x, dx, 0.0);
  CHECK(body.status() == kane::solve_status::not_finite);
  for (double v : dx) CHECK(std::isnan(v));
  // finite speeds whose gyroscopic terms overflow: u' = M^-1 f is not finite
  x[8] = 1e200, x[9] = 1e200;
  body(x, dx, 0.0);
  CHECK(body.status() == kane::solve_status::not_finite);
  for (double v : dx) CHECK(std::isnan(v));
  // NaN or inf at any entry of x, in an array (copied in blocks) and in a vector (number by number);
  // q5..q7 enter no equation but are checked
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()})
    for (std::size_t i = 0; i < 14; ++i) {
      std::array<double, 14> xa{};
      xa[0] = 1, xa[i] = bad;
      std::vector<double> xv(xa.begin(), xa.end()), dv(14);
      body(xa, dx, 0.0);
      CHECK(body.status() == kane::solve_status::not_finite);
      for (double v : dx) CHECK(std::isnan(v));
      body(xv, dv, 0.0);
      CHECK(body.status() == kane::solve_status::not_finite);
      for (double v : dv) CHECK(std::isnan(v));
    }
  x = {}, x[0] = 1;
  body(x, dx, 0.0);
  CHECK(body.status() == kane::solve_status::ok);
}

namespace {
// The rod pendulum about n1 of mass Mass and inertia I about P: M = m L^2 + I11, f = -m g L sin q.
template <auto Mass, class I>
void check_rod(double m, double i11) {
  using rod = kane::system<kane::rigid_body<A, P, Mass, I>, kane::gravity<-g * e<N, 3>>>;
  state1 s;
  s.p = {0.7, 99.0, 9.81};  // the mass parameter is not read
  s.q = {0.4};
  s.u = {1.3};
  eval1 ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<rod>(ev);
  REQUIRE(eom.status == kane::solve_status::ok);
  CHECK(eom.M(0, 0) == Approx(m * 0.49 + i11).epsilon(1e-15));
  CHECK(eom.f(0) == Approx(-m * 9.81 * 0.7 * std::sin(0.4)).epsilon(1e-14));
  // a product of 0 (or 0.0) is a type-level zero, as kane::constant<0>
  STATIC_REQUIRE(kane::is_zero_v<std::remove_cv_t<std::tuple_element_t<3, decltype(I::components)>>>);
}
}  // namespace

TEST_CASE("dynamics: plain numbers are accepted where a constant is: a mass of 2.0, products of 0.0") {
  check_rod<2, kane::inertia<A, P, 1, 2, 3, 0, 0, 0>>(2.0, 1.0);
#if !defined(__clang__)  // clang 14 takes no floating-point template argument
  check_rod<2.5, kane::inertia<A, P, 0.25, 0.5, 0.75, 0.0, 0.0, 0.0>>(2.5, 0.25);
#endif
}

TEST_CASE("dynamics: without a speed set u is q', whichever of the two the state holds") {
  using bare = kane::evaluator<state1, kane::frames<A>, kane::level::acceleration>;
  state1 by_rates, by_speeds, both, conflict;
  for (state1* s : {&by_rates, &by_speeds, &both, &conflict}) s->p = {0.7, 2.0, 9.81}, s->q = {0.4};
  by_rates.qd = {1.3}, by_rates.qdd = {-0.5};
  by_speeds.u = {1.3}, by_speeds.ud = {-0.5};
  both.qd = both.u = {1.3}, both.qdd = both.ud = {-0.5};
  conflict.qd = {1.3}, conflict.u = {0.2};
  const auto values = [](const state1& s) {
    bare ev;
    ev.update(s);
    const auto eom = kane::mass_matrix_and_forcing<pendulum>(ev);
    const kane::vec<N> a = kane::express<N>(kane::acceleration<N, P>(), ev);
    return std::array<double, 5>{eom.f(0), a[1], a[2], kane::kinetic_energy<pendulum>(ev),
                                 double(int(ev.status()))};
  };
  const auto expected = values(by_rates);
  CHECK(expected[4] == 0.0);
  CHECK(expected[3] == Approx(0.5 * 2.0 * 0.49 * 1.3 * 1.3).epsilon(1e-15));
  CHECK(values(by_speeds) == expected);
  CHECK(values(both) == expected);
  bare ev;
  ev.update(conflict);  // q' = 1.3 and u = 0.2: which one was meant is not known
  CHECK(ev.status() == kane::solve_status::conflicting_rates);
  CHECK(std::string(kane::to_string(ev.status())) == "conflicting_rates");
}

TEST_CASE("dynamics: kane::motion names x's entries and gives the evaluator at a state of x") {
  state1 s;
  s.p = {0.7, 2.0, 9.81};
  kane::motion<pendulum, eval1> f(s);
  using bare = kane::evaluator<state1, kane::frames<A>, kane::level::acceleration>;
  kane::motion<pendulum, bare> g(s);
  STATIC_REQUIRE((f.index(kane::q<1>) == 0 && f.index(kane::u<1>) == 1 && g.index(kane::u<1>) == 1));
  const std::array<double, 2> stage{0.1, -0.2}, x{0.4, 1.3};
  std::array<double, 2> dx{};
  f(stage, dx, 0.25);  // the last call, at another state: not the one asked for below
  g(stage, dx, 0.25);
  for (const double energy : {kane::kinetic_energy<pendulum>(f.evaluator(x, 0.5)),
                              kane::kinetic_energy<pendulum>(g.evaluator(x, 0.5))})
    CHECK(energy == Approx(0.5 * 2.0 * 0.49 * 1.3 * 1.3).epsilon(1e-15));
  CHECK(f.evaluator(x, 0.5).state().t == 0.5);
  CHECK(f.evaluator(x, 0.5).state().q[0] == 0.4);
  CHECK(f.evaluator(Eigen::VectorXd::Zero(3), 0.5).status() == kane::solve_status::not_finite);
}
