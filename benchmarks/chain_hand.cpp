// The hand-written outward pass for the scaling chain (chain.hpp).
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chain.hpp"

namespace chain {
template <int n>
void hand_all(const input& in, output& out) {
  using V3 = Eigen::Vector3d;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  V3 p = V3::Zero(), w = V3::Zero(), v = V3::Zero(), al = V3::Zero(), a = V3::Zero();
  Eigen::Matrix<double, 6, n> J;
  for (int i = 0; i < n; ++i) {
    const int m = (i + 1) % 6, k = m == 1 ? 2 : (m == 4 || m == 0) ? 0 : 1;
    const V3 ax = R.col(k);
    J.col(i).template head<3>() = ax;
    J.col(i).template tail<3>() = -p;
    al += in.qdd[i] * ax + in.qd[i] * w.cross(ax);
    w += in.qd[i] * ax;
    const double c = std::cos(in.q[i]), s = std::sin(in.q[i]);
    const int ia = (k + 1) % 3, ib = (k + 2) % 3;
    const V3 ea = R.col(ia), eb = R.col(ib);
    R.col(ia) = c * ea + s * eb;
    R.col(ib) = c * eb - s * ea;
    const V3 r = 0.1 * R.col(0);
    p += r;
    const V3 wr = w.cross(r);
    v += wr;
    a += al.cross(r) + w.cross(wr);
  }
  for (int i = 0; i < n; ++i)
    J.col(i).template tail<3>() = J.col(i).template head<3>().cross(p + J.col(i).template tail<3>());
  Eigen::Map<Eigen::Matrix3d>(out.R) = R;
  Eigen::Map<V3>{out.p} = p;
  Eigen::Map<V3>{out.w} = w;
  Eigen::Map<V3>{out.v} = v;
  Eigen::Map<V3>{out.alpha} = al;
  Eigen::Map<V3>{out.a} = a;
  Eigen::Map<Eigen::Matrix<double, 6, n>>{out.J} = J;
}
template void hand_all<2>(const input&, output&);
template void hand_all<4>(const input&, output&);
template void hand_all<6>(const input&, output&);
template void hand_all<10>(const input&, output&);
template void hand_all<16>(const input&, output&);
template void hand_all<20>(const input&, output&);
}  // namespace chain
