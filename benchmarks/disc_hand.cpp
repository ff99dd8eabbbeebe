// The rolling disc by hand (disc.hpp): closed forms of the lean frame,
// of A, and of the partial velocities of the centre.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "disc.hpp"

void disc::hand_partials(const input& in, output& out) {
  const double c1 = std::cos(in.q[0]), s1 = std::sin(in.q[0]), c2 = std::cos(in.q[1]), s2 = std::sin(in.q[1]);
  const double t2 = s2 / c2, r = in.r;
  const Eigen::Vector3d l1(c1, s1, 0), l2(-s1 * c2, c1 * c2, s2), l3(s1 * s2, -c1 * s2, c2);
  // u4 = r c1 (u2 - t2 u3), u5 = r s1 (u2 - t2 u3)
  Eigen::Matrix<double, 2, 3> A;
  A << 0, r * c1, -r * c1 * t2, 0, r * s1, -r * s1 * t2;
  // v = u4 n1 + u5 n2 + r (u3/c2 n3 + u1 l1) x l3
  Eigen::Matrix3d V;
  V.col(0) = -r * l2;
  V.col(1).setZero();
  V.col(2) = r / c2 * Eigen::Vector3d::UnitZ().cross(l3);
  V.row(0) += A.row(0);  // + n1 A_1s
  V.row(1) += A.row(1);  // + n2 A_2s
  Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(out.A) = A;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(out.V) = V;
}
