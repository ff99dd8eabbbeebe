// A hand-written Eigen outward pass for the 6-revolute chain (arm6.hpp):
// sin/cos once per joint, each rotation applied to two columns only,
// everything accumulated in one loop; one function per quantity.
#include <cmath>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "arm6.hpp"

namespace {
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

// R_child = R_parent Rot(axis k, q): e_a' = c e_a + s e_b, e_b' = c e_b - s e_a.
template <int k>
inline void turn(M3& R, double q) {
  const double c = std::cos(q), s = std::sin(q);
  constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
  const V3 ea = R.col(a), eb = R.col(b);
  R.col(a) = c * ea + s * eb;
  R.col(b) = c * eb - s * ea;
}
// Body(i) for i = 0..5, unrolled so that every axis index is a constant.
template <class Body>
inline void joints(Body body) {
  [&]<int... I>(std::integer_sequence<int, I...>) { (body(std::integral_constant<int, I>{}), ...); }
  (std::make_integer_sequence<int, 6>{});
}
void store(const V3& v, double* out) { Eigen::Map<V3>{out} = v; }
}  // namespace

namespace arm6 {
void hand_q1(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero();
  joints([&](auto I) {
    turn<axis[I]>(R, in.q[I]);
    p += L[I] * R.col(0);
  });
  Eigen::Map<M3>(out.R) = R;
  store(p, out.p);
}

void hand_q2(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 w = V3::Zero(), v = V3::Zero();
  joints([&](auto I) {
    w += in.qd[I] * R.col(axis[I]);
    turn<axis[I]>(R, in.q[I]);
    v += w.cross(L[I] * R.col(0));
  });
  store(w, out.w);
  store(v, out.v);
}

void hand_q3(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero();
  Eigen::Matrix<double, 6, 6> J;  // in locals: stores through out could alias in
  joints([&](auto I) {
    J.col(I).template head<3>() = R.col(axis[I]);
    J.col(I).template tail<3>() = -p;  // becomes k_i x (p_end - p_i) below
    turn<axis[I]>(R, in.q[I]);
    p += L[I] * R.col(0);
  });
  for (int i = 0; i < 6; ++i) J.col(i).tail<3>() = J.col(i).head<3>().cross(p + J.col(i).tail<3>());
  Eigen::Map<Eigen::Matrix<double, 6, 6>>{out.J} = J;
}

void hand_q4(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 w = V3::Zero(), al = V3::Zero(), a = V3::Zero();
  joints([&](auto I) {
    const V3 k = R.col(axis[I]);
    al += in.qdd[I] * k + in.qd[I] * w.cross(k);
    w += in.qd[I] * k;
    turn<axis[I]>(R, in.q[I]);
    const V3 r = L[I] * R.col(0);
    a += al.cross(r) + w.cross(w.cross(r));
  });
  store(al, out.alpha);
  store(a, out.a);
}

void hand_all(const input& in, output& out) {
  M3 R = M3::Identity();
  V3 p = V3::Zero(), w = V3::Zero(), v = V3::Zero(), al = V3::Zero(), a = V3::Zero();
  Eigen::Matrix<double, 6, 6> J;
  joints([&](auto I) {
    const V3 k = R.col(axis[I]);
    J.col(I).template head<3>() = k;
    J.col(I).template tail<3>() = -p;
    al += in.qdd[I] * k + in.qd[I] * w.cross(k);
    w += in.qd[I] * k;
    turn<axis[I]>(R, in.q[I]);
    const V3 r = L[I] * R.col(0);
    p += r;
    const V3 wr = w.cross(r);
    v += wr;
    a += al.cross(r) + w.cross(wr);
  });
  for (int i = 0; i < 6; ++i) J.col(i).tail<3>() = J.col(i).head<3>().cross(p + J.col(i).tail<3>());
  Eigen::Map<Eigen::Matrix<double, 6, 6>>{out.J} = J;
  Eigen::Map<M3>(out.R) = R;
  store(p, out.p);
  store(w, out.w);
  store(v, out.v);
  store(al, out.alpha);
  store(a, out.a);
}
}  // namespace arm6
