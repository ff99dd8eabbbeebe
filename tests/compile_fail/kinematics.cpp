// Kinematic quantities keep their frames.
// case dt_without_frame: deleted && a_vector_derivative_needs_a_frame_write_dt_A_of_v && unit<A, 1>
// case diff_without_frame: deleted && a_vector_derivative_needs_a_frame_write_diff_A_of_v_q && unit<A, 1>
// case no_chain: deleted && angular_velocities_do_not_chain_the_first_body_must_be_the_second_observer && FirstBody = A. SecondObserver = B
// case velocities_in_two_frames: deleted && quantities_measured_in_different_frames_measure_both_in_one_frame && FirstObserver = N && SecondObserver = A
// case accelerations_in_two_frames: deleted && quantities_measured_in_different_frames_measure_both_in_one_frame && FirstObserver = A && SecondObserver = N
// case angular_velocity_across_roots: kane: no path of the frame tree joins these two frames && joined_frames<A, G>
// case no_fixed_point: kane: no point on this point.s chain is fixed in the frame of differentiation && (A = A. P = P|velocity<A, P>)
// case points_not_joined: kane: no chain of points joins these two points && (P = P. Q = QA|position<P, QA>)
// case jerk: kane: the time derivative of an angular acceleration .a third derivative. is not available
// case partial_of_angular_velocity: kane: partial derivatives apply to vectors of unit vectors and scalars
// case two_point_not_fixed: kane: the two-point theorem needs both points fixed in the body frame B && (A = N. B = A. Q = P. P = M|two_point_velocity<N, A, P, M>)
// case express_across_roots: kane: no path of the frame tree joins the vector.s frames and the frame of expression && (A = G|express<G)
// case level_pose: kane: this evaluator computes no angular velocities && level::velocity
// case level_velocity: kane: this evaluator computes no angular accelerations && level::acceleration
// case frame_not_held: kane: this evaluator does not hold the frame && evaluator<State, frames<...>>
// case third_derivative_in_state: kane: a state holds q, q' and q'' only
#include <kane/kane.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, q2>> {};
struct C : kane::frame<B, kane::simple<kane::axis::x, q1>> {};
struct M0 : kane::root_frame {};
struct G : kane::frame<M0, kane::simple<kane::axis::x, q2>> {};

struct O : kane::origin<N> {};
struct P : kane::point<O, kane::q<2> * kane::e<A, 1>> {};
struct M : kane::point<P, kane::q<1> * kane::e<A, 2>> {};
struct OA : kane::origin<A> {};
struct QA : kane::point<OA, kane::q<1> * kane::e<B, 1>> {};

using St = kane::state<double, 2>;

double use() {
  St s;
  kane::evaluator<St, kane::frames<B>> ev;
  kane::evaluator<St, kane::frames<B>, kane::level::pose> ev_pose;
  kane::evaluator<St, kane::frames<B>, kane::level::velocity> ev_velocity;
  ev.update(s);
  ev_pose.update(s);
  ev_velocity.update(s);
  const auto a1 = kane::e<A, 1>;
  double x = kane::express<N>(kane::dt<N>(a1) + kane::diff<N>(a1, kane::q<1>), ev)[0];
  x += kane::express<N>(kane::angular_velocity<N, A>() + kane::angular_velocity<A, B>(), ev)[0];
  x += kane::express<N>(kane::velocity<N, P>() + kane::velocity<N, M>(), ev)[0];
  x += kane::express<N>(kane::velocity<A, QA>(), ev)[0] +
       kane::express<N>(kane::two_point_velocity<N, B, P, P>(), ev)[0];
  x += kane::express<N>(kane::e<B, 2>, ev_pose)[0] +
       kane::express<N>(kane::angular_velocity<N, B>(), ev_velocity)[0];
  x += s[kane::dt(kane::dt(kane::q<1>))];
#ifdef KANE_CASE_dt_without_frame
  x += kane::express<N>(kane::dt(a1), ev)[0];
#endif
#ifdef KANE_CASE_diff_without_frame
  x += kane::express<N>(kane::diff(a1, kane::q<1>), ev)[0];
#endif
#ifdef KANE_CASE_no_chain
  x += kane::express<N>(kane::angular_velocity<N, A>() + kane::angular_velocity<B, C>(), ev)[0];
#endif
#ifdef KANE_CASE_velocities_in_two_frames
  x += kane::express<N>(kane::velocity<N, P>() + kane::velocity<A, QA>(), ev)[0];
#endif
#ifdef KANE_CASE_accelerations_in_two_frames
  x += kane::express<N>(kane::acceleration<A, QA>() - kane::acceleration<N, P>(), ev)[0];
#endif
#ifdef KANE_CASE_angular_velocity_across_roots
  (void)kane::angular_velocity<A, G>();
#endif
#ifdef KANE_CASE_no_fixed_point
  (void)kane::velocity<A, P>();
#endif
#ifdef KANE_CASE_points_not_joined
  (void)kane::position<P, QA>();
#endif
#ifdef KANE_CASE_jerk
  (void)kane::dt<N>(kane::dt<N>(kane::dt<N>(kane::angular_velocity<N, B>())));
#endif
#ifdef KANE_CASE_partial_of_angular_velocity
  (void)kane::diff<N>(kane::angular_velocity<N, B>(), kane::q<1>);
#endif
#ifdef KANE_CASE_two_point_not_fixed
  (void)kane::two_point_velocity<N, A, P, M>();
#endif
#ifdef KANE_CASE_express_across_roots
  x += kane::express<G>(a1, ev)[0];
#endif
#ifdef KANE_CASE_level_pose
  x += kane::express<N>(kane::angular_velocity<N, B>(), ev_pose)[0];
#endif
#ifdef KANE_CASE_level_velocity
  x += kane::express<N>(kane::angular_acceleration<N, B>(), ev_velocity)[0];
#endif
#ifdef KANE_CASE_frame_not_held
  x += kane::express<N>(kane::e<C, 2>, ev)[0];  // e_C1 = e_B1 would be read from B
#endif
#ifdef KANE_CASE_third_derivative_in_state
  x += s[kane::dt(kane::dt(kane::dt(kane::q<1>)))];
#endif
  return x;
}
