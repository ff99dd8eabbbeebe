// Orocos KDL: ChainDynParam (M, Coriolis, gravity) on the chain of dynamics6.hpp; q'' by LLT;
// tau by ChainIdSolver_RNE.
#include <Eigen/Cholesky>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>

#include "dynamics6.hpp"

namespace {
struct model {
  KDL::Chain chain;
  model() {
    const KDL::Joint::JointType axis[6] = {KDL::Joint::RotZ, KDL::Joint::RotY, KDL::Joint::RotY,
                                           KDL::Joint::RotX, KDL::Joint::RotY, KDL::Joint::RotX};
    for (int i = 0; i < 6; ++i) {
      const double* j = dynamics6::inertia[i];
      // KDL::RotationalInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz) about the centre of mass, which KDL
      // places in the segment's tip frame (the link's middle is L / 2 back from the tip)
      const KDL::RigidBodyInertia body(dynamics6::mass[i],
                                       KDL::Vector(-dynamics6::L[i] / 2, 0, 0),  // KDL: in the tip frame
                                       KDL::RotationalInertia(j[0], j[1], j[2], j[3], j[5], j[4]));
      chain.addSegment(
          KDL::Segment(KDL::Joint(axis[i]), KDL::Frame(KDL::Vector(dynamics6::L[i], 0, 0)), body));
    }
  }
};
model m;
KDL::ChainDynParam dyn(m.chain, KDL::Vector(0, 0, -dynamics6::g));
KDL::ChainIdSolver_RNE rne(m.chain, KDL::Vector(0, 0, -dynamics6::g));
KDL::JntArray q(6), qd(6), qdd(6), coriolis(6), gravity(6), torques(6);
KDL::Wrenches none(6);  // no external wrenches
KDL::JntSpaceInertiaMatrix H(6);

void load(const dynamics6::input& in) {
  for (int i = 0; i < 6; ++i) q(i) = in.q[i], qd(i) = in.qd[i];
}
void mass_matrix(dynamics6::output& out) {
  dyn.JntToMass(q, H);
  // KDL allocated H for its own build's alignment, not -march=native's: read it entry by entry
  const double* h = H.data.data();
  for (int i = 0; i < 36; ++i) out.M[i] = h[i];
}
void bias(dynamics6::output& out) {
  dyn.JntToCoriolis(q, qd, coriolis);
  dyn.JntToGravity(q, gravity);
  for (int i = 0; i < 6; ++i) out.h[i] = coriolis(i) + gravity(i);
}
}  // namespace

void dynamics6::kdl_mass(const input& in, output& out) {
  load(in);
  mass_matrix(out);
}
void dynamics6::kdl_bias(const input& in, output& out) {
  load(in);
  mass_matrix(out);
  bias(out);
}
void dynamics6::kdl_forward(const input& in, output& out) {
  kdl_bias(in, out);
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(out.qdd) =
      -Eigen::Map<const Eigen::Matrix<double, 6, 6>>(out.M).llt().solve(
          Eigen::Map<const Eigen::Matrix<double, 6, 1>>(out.h));
}
void dynamics6::kdl_inverse(const input& in, output& out) {
  load(in);
  for (int i = 0; i < 6; ++i) qdd(i) = in.qdd_in[i];
  rne.CartToJnt(q, qd, qdd, none, torques);
  for (int i = 0; i < 6; ++i) out.tau[i] = torques(i);
}
