#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../examples/models/disc.hpp"
#include "trees.hpp"

using kane::solve_status;
using trees::N;

namespace {
using kane::dt, kane::q, kane::u;
struct K : kane::parameter<1> {};
struct D : kane::parameter<2> {};
constexpr K k;
constexpr D d;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double eps = std::numeric_limits<double>::epsilon();

// u = k Y0 q' with Y0 the identity, lower triangular or coupled: W = Y0^-1 / k.
using identity_speeds = kane::speeds<k * dt(q<1>), k * dt(q<2>)>;
using triangular_speeds = kane::speeds<k * dt(q<1>), k*(dt(q<1>) + 2.0 * dt(q<2>))>;
using coupled_speeds = kane::speeds<k*(2.0 * dt(q<1>) + dt(q<2>)), k*(dt(q<1>) + 3.0 * dt(q<2>))>;
static_assert(kane::detail::kde_system<identity_speeds>::form.count == 2);
static_assert(kane::detail::kde_system<triangular_speeds>::form.count == 2);
static_assert(kane::detail::kde_system<coupled_speeds>::form.count == 1);  // one Gauss-Jordan block
using St2 = kane::state<double, 2, 2, 2>;
template <class Sp>
using Ev2 = kane::evaluator<St2, kane::frames<N>, kane::level::acceleration, Sp>;

double max_abs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }
bool power_of_two(double x) {
  int e = 0;
  return std::frexp(x, &e) == 0.5;
}

// W of s Y0 is W0 / s; q' = W u and q'' = W u' (Y' = 0). s = 1e-310: Y's entries are subnormal and
// W ~ 1e310 is beyond double, so the status is not_finite (never ok) and W's numbers, q', q'' are NaN.
template <class Sp>
void check_scaled_kinematic_equations(const Eigen::Matrix2d& w0) {
  St2 s;
  s.u = {1, -2};
  s.ud = {0.5, 0.25};
  const Eigen::Vector2d uv(1, -2), udv(0.5, 0.25);
  Ev2<Sp> unit;
  s.p = {1, 0};
  unit.update(s);
  REQUIRE(unit.status() == solve_status::ok);
  for (double scale : {1.0, 1e-300, 1e300, 0x1p-1000, 0x1p1000}) {
    INFO("s = " << scale);
    s.p = {scale, 0};
    Ev2<Sp> ev;
    ev.update(s);
    REQUIRE(ev.status() == solve_status::ok);
    const Eigen::Matrix2d w = ev.W() * scale;
    CHECK(max_abs(w - w0) <= 1e-12 * max_abs(w0));
    const Eigen::Vector2d qd(ev.template coordinate_value<1, 1>(), ev.template coordinate_value<2, 1>());
    const Eigen::Vector2d qdd(ev.template coordinate_value<1, 2>(), ev.template coordinate_value<2, 2>());
    CHECK(max_abs(qd * scale - w0 * uv) <= 1e-12 * max_abs(w0 * uv));
    CHECK(max_abs(qdd * scale - w0 * udv) <= 1e-12 * max_abs(w0 * udv));
    if (power_of_two(scale))  // the very numbers of s = 1, scaled
      CHECK(max_abs(ev.W() * scale - unit.W()) == 0);
  }
  s.p = {1e-310, 0};
  Ev2<Sp> ev;
  ev.update(s);
  CHECK(ev.status() == solve_status::not_finite);
  CHECK(std::isnan(ev.W()(0, 0)));
  CHECK(std::isnan(ev.W()(1, 1)));
  CHECK(std::isnan(ev.template coordinate_value<1, 1>()));
  CHECK(std::isnan(ev.template coordinate_value<2, 2>()));
  s.p = {0, 0};
  ev.update(s);
  CHECK(ev.status() == solve_status::singular);
}

// k c_1 = 0 and k c_2 = 0 with u2, u3 dependent: the block of s M0, with R scaled alike, gives the A
// and B of M0 while M's entries are normal or subnormal (there to their rounding).
using S3 = kane::qdot_speeds<3>;
using identity_nh = kane::nonholonomic<S3, kane::dependent<2, 3>, k*(u<2> + u<1>), k*(u<3> - 0.5 * u<1>)-k>;
using triangular_nh =
    kane::nonholonomic<S3, kane::dependent<2, 3>, k*(u<2> + u<1>), k*(u<2> + 0.5 * u<3> + u<1>)-k>;
using coupled_nh = kane::nonholonomic<S3, kane::dependent<2, 3>, k*(u<2> + u<3> + u<1>), k*(u<2> - u<3>)-k>;
static_assert(kane::detail::constraint_system<identity_nh>::form.count == 2);
static_assert(kane::detail::constraint_system<triangular_nh>::form.count == 2);
static_assert(kane::detail::constraint_system<coupled_nh>::form.count == 1);
using St3 = kane::state<double, 3, 3, 2>;
using Ev3 = kane::evaluator<St3, kane::frames<N>, kane::level::pose>;

template <class NH>
void check_scaled_constraints(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  for (double scale : {1.0, 1e-300, 1e300, 1e308, 1e-310}) {
    INFO("s = " << scale);
    St3 s;
    s.p = {scale, 0};
    Ev3 ev;
    ev.update(s);
    const auto sol = kane::solve_constraints<NH>(ev);
    REQUIRE(sol.status == solve_status::ok);
    CHECK(max_abs(sol.A - a) <= 1e-12 * max_abs(a));
    CHECK(max_abs(sol.B - b) <= 1e-12 * max_abs(b));
  }
}

// u1 = k (q1' + q2'), u2 = k (q1' + (1 + d) q2'): after the first pivot k (1 + d) the second is
// about k d, against the threshold 2 eps k (1 + d).
using near_singular_speeds =
    kane::speeds<k*(dt(q<1>) + dt(q<2>)), k*(dt(q<1>) + dt(q<2>)) + k * d * dt(q<2>)>;
// The same block as constraints: A and B stay near 1/d whatever k is.
using near_singular_nh =
    kane::nonholonomic<S3, kane::dependent<2, 3>, k*(u<2> + u<3> + u<1>), k*(u<2> + u<3>)+k * d * u<3> - k>;
}  // namespace

TEST_CASE("numbers: W of s Y is W of Y / s for s = 1e-300, 1e+300 and powers of two, not finite at 1e-310",
          "[numbers]") {
  check_scaled_kinematic_equations<identity_speeds>(Eigen::Matrix2d::Identity());
  Eigen::Matrix2d triangular, coupled;
  triangular << 1, 0, -0.5, 0.5;
  coupled << 0.6, -0.2, -0.2, 0.4;
  check_scaled_kinematic_equations<triangular_speeds>(triangular);
  check_scaled_kinematic_equations<coupled_speeds>(coupled);
}

TEST_CASE("numbers: A and B of constraints scaled by 1e-300, 1e+300, 1e+308 and 1e-310 are those of s = 1",
          "[numbers]") {
  check_scaled_constraints<identity_nh>({-1, 0.5}, {0, 1});
  check_scaled_constraints<triangular_nh>({-1, 0}, {0, 2});
  check_scaled_constraints<coupled_nh>({-0.5, -0.5}, {0.5, -0.5});
}

TEST_CASE("numbers: the equilibration's power of two from the bits of x is frexp's and ldexp's",
          "[numbers]") {
  using limits = std::numeric_limits<double>;
  const auto reference = [](double x) {  // 2^-e, 2^(e-1) <= x < 2^e, e clamped so that 2^-e is normal
    int e = 0;
    std::frexp(x, &e);
    e = std::min(std::max(e, limits::min_exponent - 2), limits::max_exponent - 2);
    return std::ldexp(1.0, -e);
  };
  std::vector<double> xs = {limits::denorm_min(),
                            1e-320,
                            1e-310,
                            0x1p-1023,
                            std::nextafter(0x1p-1023, 0.0),
                            std::nextafter(0x1p-1023, 1.0),
                            limits::min(),
                            std::nextafter(limits::min(), 0.0),
                            1e-300,
                            0.5,
                            0.75,
                            1.0,
                            3.0,
                            1e300,
                            0x1p1023,
                            limits::max()};
  for (int k = -1074; k <= 1023; k += 7) xs.push_back(std::ldexp(1.3, k));
  for (double x : xs) {
    CAPTURE(x);
    CHECK(kane::detail::inverse_power_of_two(x) == reference(x));
  }
}

TEST_CASE("numbers: the rank rule near its threshold does not depend on the scale of the matrix",
          "[numbers]") {
  // The second pivot k d / (1 + d) is at or below 2 eps k (1 + d) for d <= 2 eps and above it from 3 eps on.
  const double ds[] = {0, eps / 2, eps, 2 * eps, 3 * eps, 4 * eps, 16 * eps, 1e-12};
  const solve_status expected[] = {solve_status::singular, solve_status::singular, solve_status::singular,
                                   solve_status::singular, solve_status::ok,       solve_status::ok,
                                   solve_status::ok,       solve_status::ok};
  for (int i = 0; i < 8; ++i) {
    INFO("d = " << ds[i] / eps << " eps");
    St2 s2;
    St3 s3;
    s2.p = s3.p = {1, ds[i]};
    Ev2<near_singular_speeds> unit2;
    Ev3 unit3;
    unit2.update(s2);
    unit3.update(s3);
    REQUIRE(unit2.status() == expected[i]);
    const auto unit_sol = kane::solve_constraints<near_singular_nh>(unit3);
    REQUIRE(unit_sol.status == expected[i]);
    if (expected[i] == solve_status::ok) {       // u3 = (1 + u1) / d, u2 = -u1 - u3, with 1 + d as rounded
      const double d_rounded = (1 + ds[i]) - 1;  // the block's condition number is about 4 / d
      CHECK(unit_sol.A(0, 0) == Approx(-1 - 1 / d_rounded).epsilon(1e-9));
      CHECK(unit_sol.B(1) == Approx(1 / d_rounded).epsilon(1e-9));
    }
    // s M for s not a power of two is M rounded: its pivot moves by about eps relative, which decides
    // d = 2 eps, within 2 eps of the threshold; every other status holds for every s.
    const bool edge = ds[i] == 2 * eps;
    // W ~ 1 / (k d) stays within double for k down to about 1e-290; A and B do not grow with 1 / k.
    for (double scale : {0x1p-960, 0x1p1000, 1e-280, 1e300}) {
      INFO("s = " << scale);
      s2.p = {scale, ds[i]};
      Ev2<near_singular_speeds> ev;
      ev.update(s2);
      if (edge && !power_of_two(scale)) continue;
      CHECK(ev.status() == expected[i]);
      if (expected[i] == solve_status::ok && power_of_two(scale))
        CHECK(max_abs(ev.W() * scale - unit2.W()) == 0);
    }
    for (double scale : {0x1p-960, 0x1p1000, 0x1p-1000, 1e-300, 1e300}) {
      INFO("constraints, s = " << scale);
      s3.p = {scale, ds[i]};
      Ev3 ev;
      ev.update(s3);
      const auto sol = kane::solve_constraints<near_singular_nh>(ev);
      if (edge && !power_of_two(scale)) continue;
      CHECK(sol.status == expected[i]);
      if (expected[i] == solve_status::ok && scale > 0x1p-961 && power_of_two(scale)) {
        CHECK(max_abs(sol.A - unit_sol.A) == 0);
        CHECK(max_abs(sol.B - unit_sol.B) == 0);
      }
    }
  }
}

TEST_CASE("numbers: NaN or inf in the numbers a level reads gives not_finite and NaN results", "[numbers]") {
  using body = kane::speeds<k * dt(q<1>), k*(dt(q<1>) + 2.0 * dt(q<2>))>;
  St2 good;
  good.p = {2, 0};
  good.u = {1, 2};
  good.ud = {3, 4};
  const auto bad = [&](auto field) {
    St2 s = good;
    field(s);
    return s;
  };
  const St2 states[] = {bad([](St2& s) { s.q[1] = not_a_number; }),
                        bad([](St2& s) { s.q[0] = std::numeric_limits<double>::infinity(); }),
                        bad([](St2& s) { s.u[1] = not_a_number; }),
                        bad([](St2& s) { s.ud[0] = not_a_number; }),
                        bad([](St2& s) { s.p[1] = not_a_number; }),  // a parameter no expression here reads
                        bad([](St2& s) { s.t = not_a_number; })};
  Ev2<body> ev;
  ev.update(good);
  REQUIRE(ev.status() == solve_status::ok);
  for (const St2& s : states) {
    ev.update(s);
    CHECK(ev.status() == solve_status::not_finite);
    CHECK(std::isnan(ev.W()(0, 0)));
    CHECK(std::isnan(ev.coordinate_value<1, 1>()));
    CHECK(std::isnan(ev.coordinate_value<2, 1>()));
    CHECK(std::isnan(ev.coordinate_value<1, 2>()));
    CHECK(std::isnan(ev.coordinate_value<2, 2>()));
  }
  // Numbers a level does not read do not count: u' below the acceleration level.
  kane::evaluator<St2, kane::frames<N>, kane::level::velocity, body> velocity;
  velocity.update(states[3]);
  CHECK(velocity.status() == solve_status::ok);
  CHECK(velocity.coordinate_value<2, 1>() == Approx(0.25));  // q2' = (u2 - u1) / (2 k)

  // Without a speed set: q', q'' are read from the state, and so checked.
  using St6 = trees::state6;
  kane::evaluator<St6, kane::frames<trees::C>, kane::level::velocity> pass;
  St6 s;
  s.qdd[0] = not_a_number;  // not read at the velocity level
  pass.update(s);
  CHECK(pass.status() == solve_status::ok);
  s.qd[2] = not_a_number;
  pass.update(s);
  CHECK(pass.status() == solve_status::not_finite);
  CHECK(std::isnan(kane::express<N>(kane::angular_velocity<N, trees::C>(), pass)[0]));
}

TEST_CASE("numbers: overflow of q' or q'' from finite u and W is not_finite, never ok", "[numbers]") {
  St2 s;
  s.p = {0.5, 0};  // W = 2 I
  s.u = {1e308, 1};
  Ev2<identity_speeds> ev;
  ev.update(s);
  CHECK(ev.status() == solve_status::not_finite);
  CHECK(std::isnan(ev.coordinate_value<2, 1>()));
  s.u = {1, 1};
  s.ud = {1, -1e308};
  ev.update(s);
  CHECK(ev.status() == solve_status::not_finite);
  CHECK(std::isnan(ev.coordinate_value<1, 2>()));
  CHECK(ev.coordinate_value<1, 1>() == 2);  // q' was finite: only the level that overflowed is NaN
}

TEST_CASE("numbers: constraints solved at a failed evaluator fail with its status", "[numbers]") {
  namespace disc = models::disc;
  using St5 = kane::state<double, 5, 5, 1>;
  using Ev5 = kane::evaluator<St5, kane::frames<disc::R>, kane::level::velocity, disc::speeds5>;
  St5 s;
  s.q = {0.3, 0.2, 0.1, 0, 0};
  s.u = {1, 1, 1, 0, 0};
  s.p = {0.5};
  Ev5 ev;
  ev.update(s);
  REQUIRE(kane::solve_constraints<disc::rolling>(ev).status == solve_status::ok);
  // q4, q5 (the contact point's place) enter neither Y nor the constraints' coefficients.
  s.q[4] = not_a_number;
  ev.update(s);
  CHECK(ev.status() == solve_status::not_finite);
  auto sol = kane::solve_constraints<disc::rolling>(ev);
  CHECK(sol.status == solve_status::not_finite);
  CHECK(std::isnan(sol.A(0, 1)));
  CHECK(std::isnan(sol.B(1)));
  s.q[4] = 0;
  s.u[3] = not_a_number;  // a dependent speed: the velocity level reads it
  ev.update(s);
  sol = kane::solve_constraints<disc::rolling>(ev);
  CHECK(sol.status == solve_status::not_finite);
  CHECK(std::isnan(sol.A(1, 2)));
}

TEST_CASE("numbers: finite_bits is std::isfinite of every number, at each place of a matrix and an array",
          "[numbers]") {
  constexpr double inf = std::numeric_limits<double>::infinity(), big = std::numeric_limits<double>::max();
  constexpr double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> values{0.0,  -0.0,  1.0,    -2.5, big,  -big,
                                   tiny, -tiny, 1e-310, inf,  -inf, not_a_number};
  for (const double v : values)
    for (int i = 0; i < 5; ++i) {  // three in the matrix, two in the array: i picks the one set to v
      Eigen::Vector3d m(0.5, -1.0, 3.0);
      std::array<double, 2> a{7.0, -0.25};
      if (i < 3)
        m(i) = v;
      else
        a[std::size_t(i - 3)] = v;
      CHECK(kane::detail::finite_bits(m, a) == std::isfinite(v));
      CHECK(kane::detail::finite_bits(m) == (i >= 3 || std::isfinite(v)));
    }
  CHECK(kane::detail::finite_bits(Eigen::Matrix<double, 1, 1>(inf)) == false);
  CHECK(kane::detail::finite_bits(Eigen::Matrix<double, 1, 1>(-big)) == true);
}
