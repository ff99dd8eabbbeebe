// A quadrotor: a free body on Euler parameters with four thrusts along b3 and their drag torques.
// The 12-state linearization at hover (the attitude as a rotation vector in body axes) is checked
// against central differences; LQR gains come from a Riccati iteration (Eigen only); the closed loop
// flies back to hover from a 0.5 rad tilt about a horizontal axis.
#include <array>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include <kane/kane.hpp>

#include "rk4.hpp"

namespace quad {
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
inline constexpr kane::named_parameter<1, "m"> m;    // mass
inline constexpr kane::named_parameter<2, "l"> l;    // arm length
inline constexpr kane::named_parameter<3, "k"> k;    // drag torque per unit thrust
inline constexpr kane::named_parameter<4, "g"> g;    // gravity
inline constexpr kane::named_parameter<5, "Ixy"> I;  // inertia about b1 and b2
inline constexpr kane::named_parameter<6, "Iz"> Iz;  // inertia about b3
inline constexpr kane::named_input<1, "T1"> T1;      // rotor thrusts
inline constexpr kane::named_input<2, "T2"> T2;
inline constexpr kane::named_input<3, "T3"> T3;
inline constexpr kane::named_input<4, "T4"> T4;

struct N : kane::root_frame {};
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::position_coordinates<N, 5>> {};  // q5 n1 + q6 n2 + q7 n3
struct R1 : kane::point<Bo, l * e<B, 1>> {};
struct R2 : kane::point<Bo, l * e<B, 2>> {};
struct R3 : kane::point<Bo, -l * e<B, 1>> {};
struct R4 : kane::point<Bo, -l * e<B, 2>> {};

using speeds = kane::free_body_speeds<N, B, 5>;  // body rates, then q5', q6', q7'; unit_norm<B>
using quadrotor =
    kane::system<kane::rigid_body<B, Bo, m, kane::inertia<B, Bo, I, I, Iz>>, kane::gravity<-g * e<N, 3>>,
                 kane::force<R1, T1 * e<B, 3>>, kane::force<R2, T2 * e<B, 3>>, kane::force<R3, T3 * e<B, 3>>,
                 kane::force<R4, T4 * e<B, 3>>, kane::torque<B, k*(T1 - T2 + T3 - T4) * e<B, 3>>>;
using state = kane::state_of<quadrotor, speeds>;  // kane::state<double, 7, 6, 6, 4>
using evaluator = kane::system_evaluator<quadrotor, speeds>;
using inputs = kane::inputs<T1, T2, T3, T4>;
using vector12 = Eigen::Matrix<double, 12, 1>;
}  // namespace quad

namespace {
using namespace quad;
// x~ = (dtheta, position, body rates, velocity) of x = (e, position, u) near hover (e* = 1).
vector12 tangent(const std::array<double, 13>& x) {
  const double s = x[0] < 0 ? -2 : 2;  // e and -e are one attitude
  vector12 out;
  out << s * x[1], s * x[2], s * x[3], x[4], x[5], x[6], x[7], x[8], x[9], x[10], x[11], x[12];
  return out;
}
// x at x~: e = (cos(|d| / 2), sin(|d| / 2) d / |d|)
std::array<double, 13> at(const vector12& d) {
  const double a = d.head<3>().norm(), c = std::cos(a / 2), s = a > 0 ? std::sin(a / 2) / a : 0.5;
  return {c, s * d(0), s * d(1), s * d(2), d(3), d(4), d(5), d(6), d(7), d(8), d(9), d(10), d(11)};
}
}  // namespace

int main() {
  state s;
  s[m] = 1.2, s[l] = 0.25, s[k] = 0.02, s[g] = 9.81, s[I] = 0.015, s[Iz] = 0.027;
  const double hover = s[m] * s[g] / 4;
  s.r = {hover, hover, hover, hover};
  s.q = {1, 0, 0, 0, 0, 0, 0};
  bool ok = true;

  // The 12-state model at hover, against central differences of the nonlinear right-hand side.
  const auto lin = kane::linearize_tangent<quadrotor, evaluator, inputs>(s);
  kane::motion<quadrotor, speeds> rhs(s);
  const auto rates = [&](const vector12& d, const Eigen::Vector4d& thrust) {
    std::array<double, 13> x = at(d), dx{};
    rhs.inputs() = {thrust(0), thrust(1), thrust(2), thrust(3)};
    rhs(x, dx, 0.0);
    vector12 out;  // dtheta' = 2 (e1', e2', e3') at e* = 1
    out << 2 * dx[1], 2 * dx[2], 2 * dx[3], dx[4], dx[5], dx[6], dx[7], dx[8], dx[9], dx[10], dx[11], dx[12];
    return out;
  };
  const double h = 1e-5;
  const Eigen::Vector4d t0 = Eigen::Vector4d::Constant(hover);
  double error = 0;
  for (int j = 0; j < 16; ++j) {
    vector12 dp = vector12::Zero(), dm = vector12::Zero();
    Eigen::Vector4d tp = t0, tm = t0;
    (j < 12 ? dp(j) : tp(j - 12)) += h;
    (j < 12 ? dm(j) : tm(j - 12)) -= h;
    const vector12 fd = (rates(dp, tp) - rates(dm, tm)) / (2 * h);
    const vector12 exact = j < 12 ? vector12(lin.A.col(j)) : vector12(lin.B.col(j - 12));
    error = std::fmax(error, (fd - exact).cwiseAbs().maxCoeff());
  }
  std::printf("12-state A, B against central differences: max error %.1e\n", error);
  ok = ok && lin.status == kane::solve_status::ok && error < 1e-7;

  // LQR: the discrete Riccati equation of the model sampled at dt, iterated to its fixed point.
  const double dt = 0.01;
  Eigen::Matrix<double, 16, 16> f = Eigen::Matrix<double, 16, 16>::Zero(), term, sum;
  f.topLeftCorner<12, 12>() = lin.A * dt;
  f.topRightCorner<12, 4>() = lin.B * dt;
  term = sum = Eigen::Matrix<double, 16, 16>::Identity();
  for (int n = 1; n < 20; ++n) sum += (term = term * f / n);  // exp([A B; 0 0] dt)
  const Eigen::Matrix<double, 12, 12> ad = sum.topLeftCorner<12, 12>();
  const Eigen::Matrix<double, 12, 4> bd = sum.topRightCorner<12, 4>();
  vector12 weights;
  weights << 400, 400, 100, 400, 400, 400, 4, 4, 4, 40, 40, 40;
  const Eigen::Matrix<double, 12, 12> Q = weights.asDiagonal();
  const Eigen::Matrix4d R = 0.1 * Eigen::Matrix4d::Identity();
  Eigen::Matrix<double, 12, 12> P = Q;
  Eigen::Matrix<double, 4, 12> K;
  for (int n = 0; n < 20000; ++n) {
    K = (R + bd.transpose() * P * bd).ldlt().solve(bd.transpose() * P * ad);
    const Eigen::Matrix<double, 12, 12> next = Q + ad.transpose() * P * (ad - bd * K);
    const double change = (next - P).norm();
    P = 0.5 * (next + next.transpose());
    if (change < 1e-12 * P.norm()) break;
  }

  // The closed loop from 0.5 rad about (1, 1, 0) / sqrt(2), by RK4 for 5 s.
  vector12 start = vector12::Zero();
  start.head<3>() << 0.5 / std::sqrt(2.0), 0.5 / std::sqrt(2.0), 0;
  std::array<double, 13> x = at(start);
  const double step = 1e-3;
  for (int n = 0; n < 5000; ++n) {
    const Eigen::Vector4d thrust = t0 - K * tangent(x);
    rhs.inputs() = {thrust(0), thrust(1), thrust(2), thrust(3)};
    rk4_step(rhs, x, n * step, step);
    ok = ok && rhs.status() == kane::solve_status::ok;
  }
  const double tilt = 2 * std::acos(std::fmin(1.0, std::fabs(x[0]) / std::sqrt(x[0] * x[0] + x[1] * x[1] +
                                                                               x[2] * x[2] + x[3] * x[3])));
  std::printf("attitude error after 5 s: %.1e rad\n", tilt);
  ok = ok && tilt < 1e-6;
  return ok ? 0 : 1;
}
