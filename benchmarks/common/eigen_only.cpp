// The compile-cost reference: a translation unit that only includes Eigen.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

double eigen_only(const double* q) {
  const Eigen::Matrix3d m = Eigen::AngleAxisd(q[0], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return m.determinant();
}
