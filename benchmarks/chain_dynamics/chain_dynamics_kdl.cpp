// Orocos KDL: ChainDynParam (M, Coriolis, gravity) on the n-link chain of
// chain_dynamics.hpp, built once per n; q'' by Eigen's LLT.
#include <Eigen/Cholesky>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>

#include "chain_dynamics.hpp"

namespace {
using namespace chain_dynamics;

KDL::Chain chain(std::size_t n) {
  KDL::Chain c;
  const KDL::Joint::JointType axis[3] = {KDL::Joint::RotZ, KDL::Joint::RotY, KDL::Joint::RotX};
  for (std::size_t i = 0; i < n; ++i) {
    const auto& j = inertia[i];
    // KDL::RotationalInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz) about the mass centre, which KDL
    // places in the segment's tip frame (the link's middle is L / 2 back from the tip)
    const KDL::RigidBodyInertia body(mass[i], KDL::Vector(-L[i] / 2, 0, 0),
                                     KDL::RotationalInertia(j[0], j[1], j[2], j[3], j[5], j[4]));
    c.addSegment(KDL::Segment(KDL::Joint(axis[i % 3]), KDL::Frame(KDL::Vector(L[i], 0, 0)), body));
  }
  return c;
}

template <std::size_t N>
struct model {
  KDL::Chain c = chain(N);
  KDL::ChainDynParam dyn{c, KDL::Vector(0, 0, -g)};
  KDL::JntArray q{N}, qd{N}, coriolis{N}, gravity{N};
  KDL::JntSpaceInertiaMatrix M{N};
  Eigen::VectorXd h = Eigen::VectorXd(N);
  Eigen::LLT<Eigen::MatrixXd> llt{int(N)};
};
}  // namespace

template <std::size_t N>
void chain_dynamics::kdl_forward(const input& in, output& out) {
  static model<N> m;
  for (std::size_t i = 0; i < N; ++i) m.q(i) = in.q[i], m.qd(i) = in.qd[i];
  m.dyn.JntToMass(m.q, m.M);
  m.dyn.JntToCoriolis(m.q, m.qd, m.coriolis);
  m.dyn.JntToGravity(m.q, m.gravity);
  // KDL's matrices, allocated by libkdl with its own alignment, read through unaligned maps (with
  // -march=native, Eigen in this unit assumes wider alignment than libkdl's allocations have)
  using vector = Eigen::Map<const Eigen::VectorXd, Eigen::Unaligned>;
  m.h = vector(m.coriolis.data.data(), N) + vector(m.gravity.data.data(), N);
  m.llt.compute(Eigen::Map<const Eigen::MatrixXd, Eigen::Unaligned>(m.M.data.data(), N, N));
  m.llt.solveInPlace(m.h);  // no allocation
  Eigen::Map<Eigen::Matrix<double, int(N), 1>>(out.qdd) = -m.h;
}
template void chain_dynamics::kdl_forward<6>(const input&, output&);
template void chain_dynamics::kdl_forward<12>(const input&, output&);
template void chain_dynamics::kdl_forward<24>(const input&, output&);
template void chain_dynamics::kdl_forward<48>(const input&, output&);
