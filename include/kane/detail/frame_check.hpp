// The rules of the types in one place. Each rule is a class template that is
// declared and never defined; its name says the rule and the fix, its
// arguments are the frames (or points) involved. A broken rule instantiates
//   static_assert(detail::check<ok, error::rule<A, B>>)
// and sizeof of the undefined class is the first error of g++ and clang:
//   error: invalid application of 'sizeof' to incomplete type 'kane::error::rule<N, A>'
// A rule whose fix is a call names it in a second argument, kane::fix::...:
//   In instantiation of 'kane::detail::check<false, kane::error::rule<N, A>,
//   kane::fix::call_kane_express<N>>'
// kane.hpp includes this header first, so that g++ and clang name both in the first lines.
#pragma once

#include <cstddef>
#include <type_traits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

template <class F1, class F2>
concept DifferentFrames = !std::is_same_v<F1, F2>;

namespace error {
// Components: ^N p + ^A p; write both in one frame first, e.g. express<N>(p_A, ev).
template <class LeftFrame, class RightFrame>
struct frames_differ_express_one_in_the_others_frame_first;
// vec<A> = vec<N>: change the frame with express<A>(p_N, ev).
template <class GivenFrame, class TargetFrame>
struct frames_differ_use_express_to_change_frame;
// ^C P^D * ^A P^B needs C == B: the result maps A to D.
template <class LeftFrom, class RightTo>
struct dcm_product_needs_left_from_frame_equal_right_to_frame;
// ^A P^B * ^C p needs C == A: express the components in A first.
template <class DcmFrom, class VecFrame>
struct dcm_applies_only_to_components_in_its_from_frame;
// ^A w^B + ^C w^D needs B == C, ^A w^B - ^C w^D needs A == C or B == D (eq. 10).
template <class FirstBody, class SecondObserver>
struct angular_velocities_do_not_chain_the_first_body_must_be_the_second_observer;
template <class FirstObserver, class FirstBody, class SecondObserver, class SecondBody>
struct angular_velocities_differ_only_with_one_observer_or_one_body_in_common;
// ^A v^P + ^B v^Q (also scaled, negated, summed, differentiated): measure both in one frame.
template <class FirstObserver, class SecondObserver>
struct quantities_measured_in_different_frames_measure_both_in_one_frame;
// Frames of two trees in one expression, evaluator or express.
template <class FirstRoot, class SecondRoot>
struct frames_of_two_trees_relate_them_through_a_common_root_frame;
template <class ExpressionRoot, class EvaluatorRoot>
struct expression_and_evaluator_in_two_trees_build_the_evaluator_on_the_expression_tree;
// Points: a chain joins them; velocities need a point of the chain fixed in the observer.
template <class P, class Q>
struct points_not_joined_locate_both_from_one_origin;
template <class Observer, class P>
struct no_point_of_the_chain_is_fixed_in_the_observer_locate_the_point_from_one;
// A point known by its velocity (point_by_velocity): no position from other chains, a velocity in
// its own observer only, and a velocity that is not the zero vector (a point at rest is an origin).
template <class P, class Q>
struct a_point_known_by_its_velocity_has_no_position_locate_points_from_it;
template <class Observer, class P>
struct the_velocity_of_this_point_is_known_in_another_frame_observe_it_there;
template <class Observer>
struct a_point_at_rest_is_an_origin_write_kane_origin_of_the_frame;
template <class P>
struct potential_energy_needs_positions_from_an_origin_not_from_a_point_known_by_its_velocity;
// The two-point theorem: P and Q fixed in B.
template <class Body, class Q, class P>
struct two_point_theorem_needs_both_points_fixed_in_the_body_use_one_point_velocity;
// dt(v), diff(v, q) of a vector: its derivative depends on the frame.
template <class Vector>
struct a_vector_derivative_needs_a_frame_write_dt_A_of_v;
template <class Vector>
struct a_vector_derivative_needs_a_frame_write_diff_A_of_v_q;
// partial_velocity(v, q<1>): partial velocities are d/du_r; pass u<r>.
template <class NotASpeed>
struct partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r;
// Tables of one speed set read with an evaluator or a solution of another.
template <class EvaluatorSpeeds, class TableSpeeds>
struct evaluator_and_constraints_use_different_speed_sets;
template <class SolvedConstraints, class UsedConstraints>
struct constraint_solution_of_other_constraints_solve_these;
// partial_velocity<Sp>(v, u<r>) or velocity_remainder<Sp>(v) read with an evaluator of other speeds.
template <class EvaluatorSpeeds, class PartialSpeeds>
struct partial_velocity_of_another_speed_set_build_it_for_the_evaluators;
// u_r read by an evaluator without a speed set (u = q', s.u unread): declare the speeds.
template <class Speed>
struct evaluator_without_speed_set_reads_no_u_declare_the_speed_set;
// The evaluator holds (or is one edge above) every frame it is asked for.
template <class Frame>
struct evaluator_does_not_hold_the_frame_add_it_to_frames;
// unit_norm<B> is the held row of B's Euler parameters: B must be oriented by them.
template <class Frame>
struct unit_norm_needs_a_frame_oriented_by_euler_parameters;
// Of a frame that spins by a free speed (kane::spin) only the spin axis is known: its other
// axes, and frames below it, need its angle (make it a coordinate: kane::simple).
template <class Frame>
struct a_spinning_frame_has_no_known_axes_but_its_spin_axis;
// spin<K, u<r>> and attitude<..., body_rates<u...>>: the speeds are free speeds of the
// evaluator's speed set (kane::free_speed).
template <class Frame>
struct a_frame_turns_at_free_speeds_of_the_evaluators_speed_set;
// Of a spinning frame's axes only the spin axis is known: an inertia given in it is symmetric
// about that axis (equal moments about the other two, no products).
template <class SpinningFrame>
struct inertia_in_a_spinning_frame_is_symmetric_about_its_spin_axis;
// The inertia of a rigid body is given in a frame fixed in the body (constant rotations from it).
template <class InertiaFrame, class Body>
struct inertia_given_in_a_frame_that_turns_relative_to_the_body;
// The frames of an evaluator turn by q_1 .. q_NQ of its state.
template <class Coordinate, class State>
struct a_frame_turns_by_a_coordinate_beyond_the_state;
// The inertia of a rigid body is about its mass centre; kane::parallel_axis moves it there.
template <class About, class MassCentre>
struct inertia_about_another_point_than_the_mass_centre_use_parallel_axis;
// A force acts at a particle or at a point fixed in a rigid body of the system.
template <class Point>
struct force_at_a_point_of_no_mass_apply_it_at_a_particle_or_a_point_fixed_in_a_body;
// The analytical derivatives of the dynamics take a system of joint form: each speed u_r = q_r'
// turns one edge by a simple rotation, every item below it about one point.
template <class System>
struct analytical_derivatives_need_a_tree_of_simple_rotations_with_u_equal_to_q_dot;
// ... and loads of steady components in a frame fixed in the body they act on.
template <class Load>
struct analytical_derivatives_need_loads_fixed_in_their_bodies;
// kane::evaluator_for holds the values of its reads, in the components of its tree's root.
template <class Expression>
struct evaluator_for_holds_the_values_of_its_reads_only;
template <class Frame, class Root>
struct evaluator_for_holds_its_reads_in_the_root_frame;
}  // namespace error

// The fixes that are calls or declarations, named beside their rule.
namespace fix {
// kane::express<F>(v, s) writes v's components in F.
template <class F>
struct call_kane_express;
// kane::inertia<B, Bo, ...>: components in the body's frame (or one fixed in it).
template <class Body>
struct give_the_inertia_in_the_body_frame;
// kane::inertia<F, Bo, ...> about the mass centre Bo: move it there by the parallel axis theorem.
template <class Centre>
struct give_the_inertia_about_the_mass_centre;
// kane::state<S, NQ, ...> with NQ >= I, or kane::state_of<System>.
template <std::size_t I>
struct declare_kane_state_with_nq_at_least;
// kane::linearize differentiates any system, by jets.
struct call_kane_linearize;
// kane::reads<..., x>: the evaluator_for then holds x; kane::evaluator holds the frames for any x.
struct add_it_to_kane_reads_or_use_kane_evaluator;
// kane::express<Root>(x, ev), or kane::evaluator for other frames.
template <class Root>
struct express_it_in_the_root_or_use_kane_evaluator;
}  // namespace fix

namespace detail {
template <class Rule, class Fix>
struct broken;
// true, or the first error names Rule (sizeof of an undefined class), and Fix where given.
template <bool Ok, class Rule, class Fix = void>
inline constexpr bool check = true;
template <class Rule>
inline constexpr bool check<false, Rule, void> = sizeof(Rule) > 0;
template <class Rule, class Fix>
inline constexpr bool check<false, Rule, Fix> = sizeof(broken<Rule, Fix>) > 0;
// An error that names Rule, for a branch that is always wrong.
template <class Rule, class Fix = void>
inline constexpr bool refused = check<false, Rule, Fix>;
// A base that is empty, or names Rule and Fix in the one error of the class deriving from it.
template <bool Ok, class Rule, class Fix>
struct holds {};
template <class Rule, class Fix>
struct holds<false, Rule, Fix> : broken<Rule, Fix> {};
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
