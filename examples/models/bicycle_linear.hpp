// The benchmark bicycle linearized (models/bicycle.hpp): Kane's reduced equations about
// upright straight running at speed v, exactly (jets), read as the roll/steer equations
// M q'' + C q' + K q = 0 of Meijaard et al. (2007), q = (roll q4, steer q6); C = v C1 and
// K = g K0 + v^2 K2. Shared by examples/bicycle_benchmark.cpp and tests/test_bicycle_dynamics.cpp.
#pragma once

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <type_traits>

#include "bicycle.hpp"

namespace models::bicycle {
struct lean_steer {
  Eigen::Matrix2d M, C, K;
  kane::solve_status status;
};

// Upright, straight ahead at speed v: pitch 0, the rear wheel at v / rR.
inline lean_steer linearize_upright(double v) {
  dynamics_state s = benchmark_parameters();
  s.u[6] = v / s.p[1];
  const auto eq = kane::linearize_equations<system, rolling, dynamics_evaluator, pitch>(s);
  using E = std::remove_cvref_t<decltype(eq)>;  // rows by speed, K's columns by coordinate
  constexpr Eigen::Index roll = E::row(kane::u<4>), steer = E::row(kane::u<6>);
  const auto block = [&](const auto& m, Eigen::Index c0, Eigen::Index c1) {
    return (Eigen::Matrix2d() << m(roll, c0), m(roll, c1), m(steer, c0), m(steer, c1)).finished();
  };
  return {block(eq.M, roll, steer), block(eq.C, roll, steer),
          block(eq.K, E::index(kane::q<4>), E::index(kane::q<6>)), eq.status};
}

// Eigenvalues of x' = [0 1; -M^-1 K, -M^-1 C] x, sorted by real part, then imaginary part.
inline std::array<std::complex<double>, 4> upright_eigenvalues(double v) {
  const lean_steer l = linearize_upright(v);
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a.topRightCorner<2, 2>().setIdentity();
  a.bottomLeftCorner<2, 2>() = -l.M.inverse() * l.K;
  a.bottomRightCorner<2, 2>() = -l.M.inverse() * l.C;
  const Eigen::Vector4cd e = Eigen::EigenSolver<Eigen::Matrix4d>(a, false).eigenvalues();
  std::array<std::complex<double>, 4> out{e(0), e(1), e(2), e(3)};
  std::sort(out.begin(), out.end(), [](auto x, auto y) {
    return x.real() < y.real() || (x.real() == y.real() && x.imag() < y.imag());
  });
  return out;
}

// The weave: the real part of the complex pair (NaN if none); capsize: the real eigenvalue nearest 0.
inline double weave_real_part(double v) {
  for (auto e : upright_eigenvalues(v))
    if (e.imag() > 0) return e.real();
  return std::nan("");
}
inline double capsize_eigenvalue(double v) {
  double best = INFINITY;
  for (auto e : upright_eigenvalues(v))
    if (e.imag() == 0 && std::abs(e.real()) < std::abs(best)) best = e.real();
  return best;
}
// The root of f in [lo, hi] by bisection (f(lo), f(hi) of opposite signs).
template <class F>
double bisect(F f, double lo, double hi) {
  const bool rising = f(lo) < 0;
  for (int i = 0; i < 60 && hi - lo > 1e-15; ++i) {
    const double mid = (lo + hi) / 2;
    ((f(mid) < 0) == rising ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}
}  // namespace models::bicycle
