// Kinematic quantities keep their frames, observers and trees on every leaf. Each case is a
// misuse (#ifdef) and its fix (#else): the file as it is compiles every fix.
// case dt_without_frame: a_vector_derivative_needs_a_frame_write_dt_A_of_v<kane::unit<A, 1> ?>
// case diff_without_frame: a_vector_derivative_needs_a_frame_write_diff_A_of_v_q<kane::unit<A, 1> ?>
// case no_chain: angular_velocities_do_not_chain_the_first_body_must_be_the_second_observer<A, B>
// case difference_no_common_frame: angular_velocities_differ_only_with_one_observer_or_one_body_in_common<N, A, B, C>
// case velocities_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<N, A>
// case scaled_velocities_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<N, A>
// case negated_velocities_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<A, N>
// case accelerations_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<A, N>
// case angular_accelerations_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<N, A>
// case derivative_in_two_frames: quantities_measured_in_different_frames_measure_both_in_one_frame<N, A>
// case angular_velocity_across_roots: frames_of_two_trees_relate_them_through_a_common_root_frame<N, M0>
// case sum_across_roots: frames_of_two_trees_relate_them_through_a_common_root_frame<N, M0>
// case leaf_across_roots: frames_of_two_trees_relate_them_through_a_common_root_frame<M0, N>
// case express_across_roots: frames_of_two_trees_relate_them_through_a_common_root_frame<N, M0>
// case evaluator_across_roots: frames_of_two_trees_relate_them_through_a_common_root_frame<M0, N>
// case expression_of_other_tree: expression_and_evaluator_in_two_trees_build_the_evaluator_on_the_expression_tree<N, M0>
// case no_fixed_point: no_point_of_the_chain_is_fixed_in_the_observer_locate_the_point_from_one<A, P>
// case points_not_joined: points_not_joined_locate_both_from_one_origin<P, QA>
// case position_of_velocity_point: a_point_known_by_its_velocity_has_no_position_locate_points_from_it<O, VP>
// case velocity_point_other_observer: the_velocity_of_this_point_is_known_in_another_frame_observe_it_there<A, VP>
// case velocity_point_at_rest: a_point_at_rest_is_an_origin_write_kane_origin_of_the_frame<N>
// case jerk: kane: the time derivative of an angular acceleration .a third derivative. is not available
// case partial_of_angular_velocity: kane: partial derivatives apply to vectors of unit vectors and scalars
// case two_point_not_fixed: two_point_theorem_needs_both_points_fixed_in_the_body_use_one_point_velocity<A, O, P>
// case level_pose: kane: this evaluator computes no angular velocities.*level::velocity
// case level_velocity: kane: this evaluator computes no angular accelerations.*level::acceleration
// case frame_not_held: evaluator_does_not_hold_the_frame_add_it_to_frames<C>
// case third_derivative_in_state: kane: a state holds q, q' and q'' only
// case reads_only_root: kane: these expressions read no frame but a root. hold one with kane::evaluator<State, kane::frames<F>>
// case partials_of_frame: kane: partials_of takes an expression linear in the speeds. for a frame pass its angular velocity
// case read_not_held: evaluator_for_holds_the_values_of_its_reads_only<kane::unit<A, 2> ?>, .*add_it_to_kane_reads_or_use_kane_evaluator
// case read_in_other_frame: evaluator_for_holds_its_reads_in_the_root_frame<A, N>, .*express_it_in_the_root_or_use_kane_evaluator<N>
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
struct P : kane::point<O, kane::q<2> * kane::e<A, 1>> {};            // moves in A
struct PA : kane::point<O, kane::constant<2>{} * kane::e<A, 1>> {};  // fixed in A
struct M : kane::point<P, kane::q<1> * kane::e<A, 2>> {};
struct OA : kane::origin<A> {};
struct QA : kane::point<OA, kane::q<1> * kane::e<B, 1>> {};
struct QB : kane::point<OA, kane::q<2> * kane::e<B, 2>> {};
// Points known by their velocity in N alone.
struct V : kane::point_by_velocity<N, kane::dt(kane::q<1>) * kane::e<A, 1>> {};
struct VP : kane::point<V, kane::q<2> * kane::e<B, 2>> {};
#ifdef KANE_CASE_velocity_point_at_rest
struct Rest : kane::point_by_velocity<N, kane::zero_vector{}> {};
#else
struct Rest : kane::origin<N> {};
#endif

using St = kane::state<double, 2>;

double use() {
  St s;
  kane::evaluator<St, kane::frames<B>> ev;
  kane::evaluator<St, kane::frames<C>> ev_c;
  kane::evaluator<St, kane::frames<G>> ev_g;
  kane::evaluator<St, kane::frames<B>, kane::level::pose> ev_pose;
  kane::evaluator<St, kane::frames<B>, kane::level::velocity> ev_velocity;
  ev.update(s), ev_c.update(s), ev_g.update(s), ev_pose.update(s), ev_velocity.update(s);
  const auto a1 = kane::e<A, 1>;
  const auto x0 = kane::e<N, 1>;
  double x = kane::express<M0>(kane::e<G, 2>, ev_g)[0];
  using kane::acceleration, kane::angular_acceleration, kane::angular_velocity, kane::velocity;
#ifdef KANE_CASE_dt_without_frame
  x += kane::express<N>(kane::dt(a1), ev)[0];
#else
  x += kane::express<N>(kane::dt<N>(a1), ev)[0];
#endif
#ifdef KANE_CASE_diff_without_frame
  x += kane::express<N>(kane::diff(a1, kane::q<1>), ev)[0];
#else
  x += kane::express<N>(kane::diff<N>(a1, kane::q<1>), ev)[0];
#endif
#ifdef KANE_CASE_no_chain
  x += kane::express<N>(angular_velocity<N, A>() + angular_velocity<B, C>(), ev_c)[0];
#else
  x += kane::express<N>(angular_velocity<N, A>() + angular_velocity<A, C>(), ev_c)[0];
#endif
#ifdef KANE_CASE_difference_no_common_frame
  x += kane::express<N>(angular_velocity<N, A>() - angular_velocity<B, C>(), ev_c)[0];
#else
  x += kane::express<N>(angular_velocity<N, A>() - angular_velocity<N, C>(), ev_c)[0];  // ^C w^A
#endif
#ifdef KANE_CASE_velocities_in_two_frames
  x += kane::express<N>(velocity<N, P>() + velocity<A, QA>(), ev)[0];
#else
  x += kane::express<N>(velocity<N, P>() + velocity<N, M>(), ev)[0];
#endif
#ifdef KANE_CASE_scaled_velocities_in_two_frames
  x += kane::express<N>(2.0 * velocity<N, P>() + velocity<A, QA>(), ev)[0];
#else
  x += kane::express<N>(2.0 * velocity<N, P>() + velocity<N, M>(), ev)[0];
#endif
#ifdef KANE_CASE_negated_velocities_in_two_frames
  x += kane::express<N>(-velocity<A, QA>() - velocity<N, P>() * kane::q<1>, ev)[0];
#else
  x += kane::express<N>(-velocity<A, QA>() - velocity<A, QB>() * kane::q<1>, ev)[0];
#endif
#ifdef KANE_CASE_accelerations_in_two_frames
  x += kane::express<N>(acceleration<A, QA>() - acceleration<N, P>(), ev)[0];
#else
  x += kane::express<N>(acceleration<A, QA>() - acceleration<A, QB>(), ev)[0];
#endif
#ifdef KANE_CASE_angular_accelerations_in_two_frames
  x += kane::express<N>(angular_acceleration<N, A>() + angular_acceleration<A, B>(), ev)[0];
#else
  x += kane::express<N>(angular_acceleration<N, A>() + angular_acceleration<N, B>(), ev)[0];
#endif
#ifdef KANE_CASE_derivative_in_two_frames
  x += kane::express<N>(kane::dt<N>(velocity<N, P>()) + acceleration<A, QA>(), ev)[0];
#else
  x += kane::express<N>(kane::dt<N>(velocity<N, P>()) + acceleration<N, M>(), ev)[0];
#endif
#ifdef KANE_CASE_angular_velocity_across_roots
  (void)angular_velocity<A, G>();
#else
  (void)angular_velocity<A, B>();
#endif
#ifdef KANE_CASE_sum_across_roots
  (void)(a1 + kane::e<G, 1>);
#else
  (void)(a1 + kane::e<B, 1>);
#endif
#ifdef KANE_CASE_leaf_across_roots  // the tree of a scalar factor's frames
  x += kane::express<N>(kane::dot(kane::e<G, 1>, kane::q<1> * kane::e<G, 3>) * a1, ev)[0];
#else
  x += kane::express<N>(kane::dot(kane::e<B, 1>, kane::q<1> * kane::e<B, 3>) * a1, ev)[0];
#endif
#ifdef KANE_CASE_express_across_roots
  x += kane::express<G>(a1, ev)[0];
#else
  x += kane::express<B>(a1, ev)[0];
#endif
#ifdef KANE_CASE_evaluator_across_roots
  kane::evaluator<St, kane::frames<B, G>> ev2;
#else
  kane::evaluator<St, kane::frames<B, C>> ev2;
#endif
  ev2.update(s);
  x += kane::express<N>(x0, ev2)[0];
#ifdef KANE_CASE_expression_of_other_tree
  x += kane::express<N>(a1, ev_g)[0];
#else
  x += kane::express<N>(a1, ev)[0];
#endif
#ifdef KANE_CASE_no_fixed_point
  x += kane::express<N>(velocity<A, P>(), ev)[0];
#else
  x += kane::express<N>(velocity<N, P>(), ev)[0];
#endif
#ifdef KANE_CASE_points_not_joined
  x += kane::express<N>(kane::position<P, QA>(), ev)[0];
#else
  x += kane::express<N>(kane::position<P, M>(), ev)[0];
#endif
#ifdef KANE_CASE_jerk
  (void)kane::dt<N>(kane::dt<N>(angular_velocity<N, B>()));
#else
  (void)kane::dt<N>(angular_velocity<N, B>());
#endif
#ifdef KANE_CASE_partial_of_angular_velocity
  (void)kane::diff<N>(angular_velocity<N, B>(), kane::q<1>);
#else
  (void)kane::diff<N>(kane::position<O, M>(), kane::q<1>);
#endif
#ifdef KANE_CASE_two_point_not_fixed  // r^OP = q2 a1 changes in A
  x += kane::express<N>(kane::two_point_velocity<N, A, O, P>(), ev)[0];
#else
  x += kane::express<N>(kane::two_point_velocity<N, A, O, PA>(), ev)[0];
#endif
#ifdef KANE_CASE_level_pose
  x += kane::express<N>(angular_velocity<N, B>(), ev_pose)[0];
#else
  x += kane::express<N>(angular_velocity<N, B>(), ev_velocity)[0];
#endif
#ifdef KANE_CASE_level_velocity
  x += kane::express<N>(angular_acceleration<N, B>(), ev_velocity)[0];
#else
  x += kane::express<N>(angular_acceleration<N, B>(), ev)[0];
#endif
#ifdef KANE_CASE_position_of_velocity_point
  x += kane::express<N>(kane::position<O, VP>(), ev)[0];
#else
  x += kane::express<N>(kane::position<V, VP>(), ev)[0];
#endif
#ifdef KANE_CASE_velocity_point_other_observer
  x += kane::express<N>(velocity<A, VP>(), ev)[0];
#else
  x += kane::express<N>(velocity<N, VP>() + acceleration<N, VP>() + velocity<N, Rest>(), ev)[0];
#endif
#ifdef KANE_CASE_frame_not_held
  x += kane::express<N>(kane::e<C, 2>, ev)[0];  // e_C1 = e_B1 would be read from B
#else
  x += kane::express<N>(kane::e<C, 2>, ev_c)[0];
#endif
#ifdef KANE_CASE_reads_only_root
  kane::evaluator_for<St, kane::reads<kane::e<N, 1>>> ev_for;
#else
  kane::evaluator_for<St, kane::reads<kane::e<A, 1>>> ev_for;
#endif
  ev_for.update(s);
#ifdef KANE_CASE_read_not_held
  x += kane::express<N>(kane::e<A, 2>, ev_for)[0];
#else
  x += kane::express<N>(kane::e<A, 1>, ev_for)[0];
#endif
#ifdef KANE_CASE_read_in_other_frame
  x += kane::express<A>(kane::e<A, 1>, ev_for)[0];
#else
  x += kane::express<N>(kane::e<A, 1>, ev_for)[1];
#endif
#ifdef KANE_CASE_partials_of_frame
  kane::evaluator_for<St, kane::reads<kane::partials_of(B{})>> ev_partials;
#else
  kane::evaluator_for<St, kane::reads<kane::partials_of(angular_velocity<N, B>())>> ev_partials;
#endif
  ev_partials.update(s);
  x += kane::partial_velocities<N>(angular_velocity<N, B>(), ev_partials)(0, 0);
#ifdef KANE_CASE_third_derivative_in_state
  x += s[kane::dt(kane::dt(kane::dt(kane::q<1>)))];
#else
  x += s[kane::dt(kane::dt(kane::q<1>))];
#endif
  return x;
}
