// The benchmark bicycle's eigenvalues from its linearization (bicycle_linear.hpp), compiled once.
#include <Eigen/LU>
#include <cmath>
#include <kane/linearization/eigenvalues.hpp>

#include "bicycle_linear.hpp"

namespace models::bicycle {
std::array<std::complex<double>, 4> upright_eigenvalues(double v) {
  const lean_steer l = linearize_upright(v);
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a.topRightCorner<2, 2>().setIdentity();
  a.bottomLeftCorner<2, 2>() = -l.M.inverse() * l.K;
  a.bottomRightCorner<2, 2>() = -l.M.inverse() * l.C;
  const auto e = kane::eigenvalues(a).values;  // sorted by real, then imaginary part
  const std::array<std::complex<double>, 4> out{e(0), e(1), e(2), e(3)};
  return out;
}

double weave_real_part(double v) {
  for (auto e : upright_eigenvalues(v))
    if (e.imag() > 0) return e.real();
  return std::nan("");
}
double capsize_eigenvalue(double v) {
  double best = INFINITY;
  for (auto e : upright_eigenvalues(v))
    if (e.imag() == 0 && std::abs(e.real()) < std::abs(best)) best = e.real();
  return best;
}
}  // namespace models::bicycle
