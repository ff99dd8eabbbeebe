// A hand-written Eigen outward pass for the 6-revolute chain (arm6.hpp):
// sin/cos once per joint, each rotation applied to two columns only,
// everything accumulated in one loop; one function per quantity.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "arm6.hpp"

namespace {
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

// R_child = R_parent Rot(axis k, q): e_a' = c e_a + s e_b, e_b' = c e_b - s e_a.
inline void turn(M3& R, int k, double q) {
  const double c = std::cos(q), s = std::sin(q);
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  const V3 ea = R.col(a), eb = R.col(b);
  R.col(a) = c * ea + s * eb;
  R.col(b) = c * eb - s * ea;
}
void store(const V3& v, double* out) { Eigen::Map<V3>{out} = v; }
}  // namespace

namespace arm6 {
void hand_q1(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero();
  for (int i = 0; i < 6; ++i) {
    turn(R, axis[i], in.q[i]);
    p += L[i] * R.col(0);
  }
  Eigen::Map<M3>(out.R) = R;
  store(p, out.p);
}

void hand_q2(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 w = V3::Zero(), v = V3::Zero();
  for (int i = 0; i < 6; ++i) {
    w += in.qd[i] * R.col(axis[i]);
    turn(R, axis[i], in.q[i]);
    v += w.cross(L[i] * R.col(0));
  }
  store(w, out.w);
  store(v, out.v);
}

void hand_q3(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero();
  Eigen::Map<Eigen::Matrix<double, 6, 6>> J(out.J);
  for (int i = 0; i < 6; ++i) {
    J.col(i).head<3>() = R.col(axis[i]);
    J.col(i).tail<3>() = -p;  // becomes k_i x (p_end - p_i) below
    turn(R, axis[i], in.q[i]);
    p += L[i] * R.col(0);
  }
  for (int i = 0; i < 6; ++i) J.col(i).tail<3>() = J.col(i).head<3>().cross(p + J.col(i).tail<3>());
}

void hand_q4(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 w = V3::Zero(), al = V3::Zero(), a = V3::Zero();
  for (int i = 0; i < 6; ++i) {
    const V3 k = R.col(axis[i]);
    al += in.qdd[i] * k + in.qd[i] * w.cross(k);
    w += in.qd[i] * k;
    turn(R, axis[i], in.q[i]);
    const V3 r = L[i] * R.col(0);
    a += al.cross(r) + w.cross(w.cross(r));
  }
  store(al, out.alpha);
  store(a, out.a);
}

void hand_all(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero(), w = V3::Zero(), v = V3::Zero(), al = V3::Zero(), a = V3::Zero();
  Eigen::Map<Eigen::Matrix<double, 6, 6>> J(out.J);
  for (int i = 0; i < 6; ++i) {
    const V3 k = R.col(axis[i]);
    J.col(i).head<3>() = k;
    J.col(i).tail<3>() = -p;
    al += in.qdd[i] * k + in.qd[i] * w.cross(k);
    w += in.qd[i] * k;
    turn(R, axis[i], in.q[i]);
    const V3 r = L[i] * R.col(0);
    p += r;
    const V3 wr = w.cross(r);
    v += wr;
    a += al.cross(r) + w.cross(wr);
  }
  for (int i = 0; i < 6; ++i) J.col(i).tail<3>() = J.col(i).head<3>().cross(p + J.col(i).tail<3>());
  Eigen::Map<M3>(out.R) = R;
  store(p, out.p);
  store(w, out.w);
  store(v, out.v);
  store(al, out.alpha);
  store(a, out.a);
}
}  // namespace arm6
