// kane: Kane's equations of the 6-revolute chain with link masses (dynamics6.hpp, the
// model of examples/models/arm6_dynamics.hpp), written as the README teaches: the entry
// points of a system of joint form read the pose alone of an evaluator (level::pose).
#include "../../examples/models/arm6_dynamics.hpp"
#include "dynamics6.hpp"

namespace {
using namespace models::arm6;
using system = links;
using state = kane::state<double, 6>;
using evaluator = kane::evaluator<state, kane::frames<B6>, kane::level::pose, kane::qdot_speeds<6>>;
using vector = Eigen::Map<Eigen::Matrix<double, 6, 1>>;

state at(const dynamics6::input& in) {
  state s;
  s.q = in.q, s.u = in.qd;
  return s;
}
// M alone
void mass_alone(const dynamics6::input& in, dynamics6::output& out) {
  evaluator ev;
  ev.update(at(in));
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.M) = kane::mass_matrix<system>(ev).M;
}
// M and h = -f
void mass_and_bias(const dynamics6::input& in, dynamics6::output& out) {
  evaluator ev;
  ev.update(at(in));
  const auto eom = kane::mass_matrix_and_forcing<system>(ev);
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.M) = eom.M;
  vector(out.h) = -eom.f;
}
// q''
void forward(const dynamics6::input& in, dynamics6::output& out) {
  evaluator ev;
  ev.update(at(in));
  vector(out.qdd) = kane::forward_dynamics<system>(ev).ud;
}
// tau = M q''_in - f
void inverse(const dynamics6::input& in, dynamics6::output& out) {
  state s = at(in);
  s.ud = in.qdd_in;
  evaluator ev;
  ev.update(s);
  vector(out.tau) = kane::inverse_dynamics<system>(ev).tau;
}
// tau and its derivatives by q and q'
void inverse_derivatives(const dynamics6::input& in, dynamics6::output& out) {
  state s = at(in);
  s.ud = in.qdd_in;
  evaluator ev;
  ev.update(s);
  const auto d = kane::inverse_dynamics_derivatives<system>(ev);
  vector(out.tau) = d.tau;
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.dq) = d.dtau_dq,
                                      Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.du) = d.dtau_du;
}
// q'' and its derivatives by q and q'
void forward_derivatives(const dynamics6::input& in, dynamics6::output& out) {
  evaluator ev;
  ev.update(at(in));
  const auto d = kane::forward_dynamics_derivatives<system>(ev);
  vector(out.qdd) = d.ud;
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.dq) = d.dud_dq,
                                      Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.du) = d.dud_du;
}
}  // namespace

void dynamics6::kane_inverse_derivatives(const input& in, output& out) { inverse_derivatives(in, out); }
void dynamics6::kane_forward_derivatives(const input& in, output& out) { forward_derivatives(in, out); }
void dynamics6::kane_mass(const input& in, output& out) { mass_alone(in, out); }
void dynamics6::kane_bias(const input& in, output& out) { mass_and_bias(in, out); }
void dynamics6::kane_forward(const input& in, output& out) { forward(in, out); }
void dynamics6::kane_inverse(const input& in, output& out) { inverse(in, out); }
