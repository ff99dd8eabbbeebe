// Hand-written: the composite-rigid-body algorithm for M and the recursive
// Newton-Euler algorithm for h (q'' = 0, gravity as a base acceleration), both in
// spatial vectors (w, v_O) in N's components, fixed-size Eigen; q'' by LLT.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "dynamics6.hpp"

namespace {
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using V6 = Eigen::Matrix<double, 6, 1>;
using M6 = Eigen::Matrix<double, 6, 6>;
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};  // z, y, y, x, y, x

M3 skew(const V3& c) {
  M3 s;
  s << 0, -c.z(), c.y(), c.z(), 0, -c.x(), -c.y(), c.x(), 0;
  return s;
}
V6 cross_motion(const V6& a, const V6& b) {  // a x b for motion vectors
  V6 r;
  r.head<3>() = a.head<3>().cross(b.head<3>());
  r.tail<3>() = a.head<3>().cross(b.tail<3>()) + a.tail<3>().cross(b.head<3>());
  return r;
}
V6 cross_force(const V6& a, const V6& f) {  // a x* f
  V6 r;
  r.head<3>() = a.head<3>().cross(f.head<3>()) + a.tail<3>().cross(f.tail<3>());
  r.tail<3>() = a.head<3>().cross(f.tail<3>());
  return r;
}

struct links {
  V6 S[6];  // joint axes (z_i, p_i x z_i)
  M6 I[6];  // spatial inertias about N's origin
};

links kinematics(const dynamics6::input& in) {
  links k;
  M3 R = M3::Identity();
  V3 p = V3::Zero();
  for (int i = 0; i < 6; ++i) {
    const double c = std::cos(in.q[i]), s = std::sin(in.q[i]);
    M3 e = M3::Identity();  // rotation about the local axis
    const int a = (axis[i] + 1) % 3, b = (axis[i] + 2) % 3;
    e(a, a) = c, e(a, b) = -s, e(b, a) = s, e(b, b) = c;
    const V3 z = R.col(axis[i]);
    R = R * e;
    k.S[i] << z, p.cross(z);
    const double* j = dynamics6::inertia[i];
    M3 ib;
    ib << j[0], j[3], j[5], j[3], j[1], j[4], j[5], j[4], j[2];
    const double m = dynamics6::mass[i];
    const V3 cm = p + 0.5 * dynamics6::L[i] * R.col(0);
    const M3 cx = skew(cm);
    k.I[i].topLeftCorner<3, 3>() = R * ib * R.transpose() - m * cx * cx;
    k.I[i].topRightCorner<3, 3>() = m * cx;
    k.I[i].bottomLeftCorner<3, 3>() = -m * cx;
    k.I[i].bottomRightCorner<3, 3>() = m * M3::Identity();
    p += dynamics6::L[i] * R.col(0);
  }
  return k;
}

void mass_matrix(const links& k, dynamics6::output& out) {
  Eigen::Map<Eigen::Matrix<double, 6, 6>> M(out.M);
  M6 composite = k.I[5];
  for (int i = 5; i >= 0; --i) {
    if (i < 5) composite += k.I[i];
    const V6 f = composite * k.S[i];
    for (int j = 0; j <= i; ++j) M(i, j) = M(j, i) = k.S[j].dot(f);
  }
}

void bias(const links& k, const dynamics6::input& in, dynamics6::output& out) {
  V6 v = V6::Zero(), a;
  a << 0, 0, 0, 0, 0, dynamics6::g;  // the base accelerates up: gravity
  V6 f[6];
  for (int i = 0; i < 6; ++i) {
    const V6 vp = v;
    v += k.S[i] * in.qd[i];
    a += cross_motion(vp, v);
    f[i] = k.I[i] * a + cross_force(v, k.I[i] * v);
  }
  for (int i = 5; i >= 0; --i) {
    if (i < 5) f[i] += f[i + 1];
    out.h[i] = k.S[i].dot(f[i]);
  }
}
}  // namespace

void dynamics6::hand_mass(const input& in, output& out) { mass_matrix(kinematics(in), out); }
void dynamics6::hand_bias(const input& in, output& out) {
  const links k = kinematics(in);
  mass_matrix(k, out);
  bias(k, in, out);
}
void dynamics6::hand_forward(const input& in, output& out) {
  hand_bias(in, out);
  const Eigen::Map<const Eigen::Matrix<double, 6, 6>> M(out.M);
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(out.qdd) =
      -M.llt().solve(Eigen::Map<const Eigen::Matrix<double, 6, 1>>(out.h));
}
