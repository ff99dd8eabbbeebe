// kane's Whipple bicycle (bicycle.hpp, models/bicycle.hpp): kane_rates is the integrator's
// right-hand side kane::constrained_motion, built once with the parameters and called per
// state; kane_A is kane::linearize_constrained (jets of the 6 directions of x_ind that the
// equations read, none for the contact position q1, q2; the pitch's jet from the holonomic
// constraint's partial derivatives) at the input's state.
#include "../../examples/models/bicycle.hpp"
#include "bicycle.hpp"

namespace {
namespace b = models::bicycle;
using rhs = kane::constrained_motion<b::system, b::rolling, b::dynamics_evaluator>;

b::dynamics_state parameters() {
  b::dynamics_state s;
  for (std::size_t i = 0; i < 27; ++i) s.p[i] = bicycle::p[i];
  return s;
}
rhs motion{parameters()};
}  // namespace

void bicycle::kane_rates(const input& in, rates& out) { motion(in.x, out.xd, 0.0); }

void bicycle::kane_A(const input& in, linear& out) {
  b::dynamics_state s;
  for (std::size_t i = 0; i < 27; ++i) s.p[i] = p[i];
  for (std::size_t i = 0; i < 6; ++i) s.q[i] = in.x[i];
  s.u[3] = in.x[6], s.u[5] = in.x[7], s.u[6] = in.x[8];
  const auto lin = kane::linearize_constrained<b::system, b::rolling, b::dynamics_evaluator, b::pitch>(s);
  Eigen::Map<Eigen::Matrix<double, 8, 8, Eigen::RowMajor>>(out.A) = lin.A;
}
