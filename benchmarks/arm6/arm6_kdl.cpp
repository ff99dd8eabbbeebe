// Orocos KDL, the peer a robotics user would pick, on the 6-revolute chain
// (arm6.hpp): its recursive solvers for pose, velocity and Jacobian, and for
// accelerations J q'' + J' q' (KDL 1.5 has no acceleration forward solver).
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainfksolvervel_recursive.hpp>
#include <kdl/chainjnttojacdotsolver.hpp>
#include <kdl/chainjnttojacsolver.hpp>

#include "arm6.hpp"

namespace {
struct model {
  KDL::Chain chain;
  model() {
    const KDL::Joint::JointType axis[6] = {KDL::Joint::RotZ, KDL::Joint::RotY, KDL::Joint::RotY,
                                           KDL::Joint::RotX, KDL::Joint::RotY, KDL::Joint::RotX};
    for (int i = 0; i < 6; ++i)
      chain.addSegment(KDL::Segment(KDL::Joint(axis[i]), KDL::Frame(KDL::Vector(arm6::L[i], 0, 0))));
  }
};
model m;
KDL::ChainFkSolverPos_recursive fk_pos(m.chain);
KDL::ChainFkSolverVel_recursive fk_vel(m.chain);
KDL::ChainJntToJacSolver jac_solver(m.chain);
KDL::ChainJntToJacDotSolver jacdot_solver(m.chain);
KDL::JntArray q(6), qd(6), qdd(6);
KDL::Jacobian J(6), Jd(6);

void load(const arm6::input& in) {
  for (int i = 0; i < 6; ++i) q(i) = in.q[i], qd(i) = in.qd[i], qdd(i) = in.qdd[i];
}
void q1(arm6::output& out) {
  KDL::Frame f;
  fk_pos.JntToCart(q, f);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out.R[3 * c + r] = f.M(r, c);
  for (int i = 0; i < 3; ++i) out.p[i] = f.p(i);
}
void q2(arm6::output& out) {
  KDL::FrameVel f;
  fk_vel.JntToCart(KDL::JntArrayVel(q, qd), f);
  for (int i = 0; i < 3; ++i) out.w[i] = f.M.w(i), out.v[i] = f.p.v(i);
}
void q3(arm6::output& out) {
  jac_solver.JntToJac(q, J);
  for (int c = 0; c < 6; ++c)
    for (int r = 0; r < 3; ++r) out.J[6 * c + r] = J(r + 3, c), out.J[6 * c + 3 + r] = J(r, c);
}
void q4(arm6::output& out) {
  jac_solver.JntToJac(q, J);
  jacdot_solver.JntToJacDot(KDL::JntArrayVel(q, qd), Jd);
  for (int r = 0; r < 3; ++r) {
    double lin = 0, ang = 0;
    for (int c = 0; c < 6; ++c) {
      lin += J(r, c) * qdd(c) + Jd(r, c) * qd(c);
      ang += J(r + 3, c) * qdd(c) + Jd(r + 3, c) * qd(c);
    }
    out.a[r] = lin, out.alpha[r] = ang;
  }
}
}  // namespace

namespace arm6 {
void kdl_q1(const input& in, output& out) { load(in), q1(out); }
void kdl_q2(const input& in, output& out) { load(in), q2(out); }
void kdl_q3(const input& in, output& out) { load(in), q3(out); }
void kdl_q4(const input& in, output& out) { load(in), q4(out); }
void kdl_all(const input& in, output& out) { load(in), q1(out), q2(out), q3(out), q4(out); }
}  // namespace arm6
