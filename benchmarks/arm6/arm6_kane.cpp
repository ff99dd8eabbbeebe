// kane's implementation of the 6-revolute chain (arm6.hpp).
#include "../../examples/models/arm6.hpp"
#include "arm6.hpp"

namespace {
using namespace models::arm6;

using state = kane::state<double, 6>;

constexpr auto r_end = kane::position<O, End>();
constexpr auto w6 = kane::angular_velocity<N, B6>();
constexpr auto v_end = kane::velocity<N, End>();
constexpr auto alpha6 = kane::angular_acceleration<N, B6>();
constexpr auto a_end = kane::acceleration<N, End>();
// Each evaluator holds the values its rows read (kane::evaluator_for): update runs the outward pass
// over the frames they read, B1 .. B6 for the pose and B1 .. B5 for the rest (B6 is one edge
// below B5 and e_B6,1 = e_B5,1), and keeps only the values.
using pose_reads = kane::reads<r_end, kane::e<B6, 1>, kane::e<B6, 2>, kane::e<B6, 3>>;
using velocity_reads = kane::reads<w6, v_end>;
using jacobian_reads = kane::reads<kane::partials_of(w6), kane::partials_of(v_end)>;
using acceleration_reads = kane::reads<alpha6, a_end>;
using all_reads = kane::reads<r_end, kane::e<B6, 1>, kane::e<B6, 2>, kane::e<B6, 3>, w6, v_end,
                              kane::partials_of(w6), kane::partials_of(v_end), alpha6, a_end>;

template <class V>
void store(const V& v, double* out) {
  out[0] = v[0], out[1] = v[1], out[2] = v[2];
}
template <class Ev>
void q1(const Ev& ev, arm6::output& out) {
  store(kane::express<N>(kane::e<B6, 1>, ev), out.R);
  store(kane::express<N>(kane::e<B6, 2>, ev), out.R + 3);
  store(kane::express<N>(kane::e<B6, 3>, ev), out.R + 6);
  store(kane::express<N>(r_end, ev), out.p);
}
template <class Ev>
void q2(const Ev& ev, arm6::output& out) {
  store(kane::express<N>(w6, ev), out.w);
  store(kane::express<N>(v_end, ev), out.v);
}
template <class Ev>
void q3(const Ev& ev, arm6::output& out) {
  Eigen::Map<Eigen::Matrix<double, 6, 6>> J(out.J);
  J.topRows<3>() = kane::partial_velocities<N>(w6, ev);
  J.bottomRows<3>() = kane::partial_velocities<N>(v_end, ev);
}
template <class Ev>
void q4(const Ev& ev, arm6::output& out) {
  store(kane::express<N>(alpha6, ev), out.alpha);
  store(kane::express<N>(a_end, ev), out.a);
}
// What a controller keeps across calls: its state and evaluators, updated at each call.
struct kept {
  state s;
  kane::evaluator_for<state, pose_reads> pose;
  kane::evaluator_for<state, velocity_reads> velocity;
  kane::evaluator_for<state, jacobian_reads> jacobian;
  kane::evaluator_for<state, acceleration_reads> acceleration;
  kane::evaluator_for<state, all_reads> every;
} held;
}  // namespace

namespace arm6 {
void kane_q1(const input& in, output& out) {
  state s;
  kane::evaluator_for<state, pose_reads> ev_pose;
  s.q = in.q;
  ev_pose.update(s);
  q1(ev_pose, out);
}
void kane_q2(const input& in, output& out) {
  state s;
  kane::evaluator_for<state, velocity_reads> ev_velocity;
  s.q = in.q;
  s.qd = in.qd;
  ev_velocity.update(s);
  q2(ev_velocity, out);
}
void kane_q3(const input& in, output& out) {
  state s;
  kane::evaluator_for<state, jacobian_reads> ev_jacobian;
  s.q = in.q;
  ev_jacobian.update(s);
  q3(ev_jacobian, out);
}
void kane_q4(const input& in, output& out) {
  state s;
  kane::evaluator_for<state, acceleration_reads> ev_acceleration;
  s.q = in.q;
  s.qd = in.qd;
  s.qdd = in.qdd;
  ev_acceleration.update(s);
  q4(ev_acceleration, out);
}
void kane_all(const input& in, output& out) {
  state s;
  kane::evaluator_for<state, all_reads> ev_all;
  s.q = in.q;
  s.qd = in.qd;
  s.qdd = in.qdd;
  ev_all.update(s);
  q1(ev_all, out);
  q2(ev_all, out);
  q3(ev_all, out);
  q4(ev_all, out);
}
// the same with the state and the evaluators kept across calls, as a controller keeps them
void kane_kept_q1(const input& in, output& out) {
  held.s.q = in.q;
  held.pose.update(held.s);
  q1(held.pose, out);
}
void kane_kept_q2(const input& in, output& out) {
  held.s.q = in.q, held.s.qd = in.qd;
  held.velocity.update(held.s);
  q2(held.velocity, out);
}
void kane_kept_q3(const input& in, output& out) {
  held.s.q = in.q;
  held.jacobian.update(held.s);
  q3(held.jacobian, out);
}
void kane_kept_q4(const input& in, output& out) {
  held.s.q = in.q, held.s.qd = in.qd, held.s.qdd = in.qdd;
  held.acceleration.update(held.s);
  q4(held.acceleration, out);
}
void kane_kept_all(const input& in, output& out) {
  held.s.q = in.q, held.s.qd = in.qd, held.s.qdd = in.qdd;
  held.every.update(held.s);
  q1(held.every, out), q2(held.every, out), q3(held.every, out), q4(held.every, out);
}
}  // namespace arm6
