// A hand-written Eigen outward pass for the 6-revolute chain (arm6.hpp):
// sin/cos once per joint, each rotation applied to two columns only.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "arm6.hpp"

namespace {
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};

// Columns of R_child = R_parent * Rot(axis, q): e_a' = c e_a + s e_b, e_b' = c e_b - s e_a.
inline void turn(Eigen::Matrix3d& R, int k, double c, double s) {
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  const Eigen::Vector3d ea = R.col(a), eb = R.col(b);
  R.col(a) = c * ea + s * eb;
  R.col(b) = c * eb - s * ea;
}
}  // namespace

namespace arm6 {
void hand_pose(const input& in, output& out) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < 6; ++i) {
    turn(R, axis[i], std::cos(in.q[i]), std::sin(in.q[i]));
    p += L[i] * R.col(0);
  }
  Eigen::Map<Eigen::Matrix3d>(out.R) = R;
  Eigen::Map<Eigen::Vector3d>(out.p) = p;
}

void hand_all(const input& in, output& out) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = p, a = p, w = p, al = p;
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d k = R.col(axis[i]);  // joint axis, fixed in parent and child
    al += in.qdd[i] * k + in.qd[i] * w.cross(k);
    w += in.qd[i] * k;
    turn(R, axis[i], std::cos(in.q[i]), std::sin(in.q[i]));
    const Eigen::Vector3d r = L[i] * R.col(0);
    p += r;
    const Eigen::Vector3d wr = w.cross(r);
    v += wr;
    a += al.cross(r) + w.cross(wr);
  }
  Eigen::Map<Eigen::Matrix3d>(out.R) = R;
  Eigen::Map<Eigen::Vector3d>(out.p) = p;
  Eigen::Map<Eigen::Vector3d>(out.w) = w;
  Eigen::Map<Eigen::Vector3d>(out.v) = v;
  Eigen::Map<Eigen::Vector3d>(out.alpha) = al;
  Eigen::Map<Eigen::Vector3d>(out.a) = a;
}
}  // namespace arm6
