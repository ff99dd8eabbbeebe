// The benchmark bicycle linearized (models/bicycle.hpp): Kane's reduced equations about
// upright straight running at speed v, exactly (jets), read as the roll/steer equations
// M q'' + C q' + K q = 0 of Meijaard et al. (2007), q = (roll q4, steer q6); C = v C1 and
// K = g K0 + v^2 K2. Shared by examples/bicycle_benchmark.cpp and tests/test_bicycle_dynamics.cpp.
// This header holds no model: the equations are compiled once, in bicycle_linear.cpp (the
// eigenvalues in bicycle_eigenvalues.cpp), behind plain functions, so that the files that include
// it compile in seconds.
#pragma once

#include <Eigen/Core>
#include <array>
#include <complex>

#include <kane/evaluation/status.hpp>

namespace models::bicycle {
struct lean_steer {
  Eigen::Matrix2d M, C, K;
  kane::solve_status status;
};

// Upright, straight ahead at speed v: pitch 0, the rear wheel at v / rR. Compiled once, in
// bicycle_linear.cpp: a file that calls it compiles in seconds.
lean_steer linearize_upright(double v);

// Eigenvalues of x' = [0 1; -M^-1 K, -M^-1 C] x, sorted by real part, then imaginary part.
std::array<std::complex<double>, 4> upright_eigenvalues(double v);
// The weave: the real part of the complex pair (NaN if none); capsize: the real eigenvalue nearest 0.
double weave_real_part(double v);
double capsize_eigenvalue(double v);
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
