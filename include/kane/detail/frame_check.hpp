// The frame checks in one place. A mismatch selects a deleted overload whose
// signature carries one of these tags, so the first error line names the rule,
// the fix and both frames ([with LeftFrame = N; RightFrame = A]).
#pragma once

#include <type_traits>

namespace kane {

template <class F1, class F2>
concept DifferentFrames = !std::is_same_v<F1, F2>;

namespace error {
// ^N p + ^A p: write both in one frame first, e.g. express<N>(p_A, state).
template <class LeftFrame, class RightFrame>
struct frames_differ_express_one_in_the_others_frame_first {};
// vec<A> = vec<N>: change the frame with express<A>(p_N, state).
template <class GivenFrame, class TargetFrame>
struct frames_differ_use_express_to_change_frame {};
// ^C P^D * ^A P^B needs C == B: the result maps A to D.
template <class LeftFrom, class RightTo>
struct dcm_product_needs_left_from_frame_equal_right_to_frame {};
// ^A P^B * ^C p needs C == A: express the components in A first.
template <class DcmFrom, class VecFrame>
struct dcm_applies_only_to_components_in_its_from_frame {};
// ^A w^B + ^C w^D needs B == C (eq. 10): the sum is ^A w^D.
template <class FirstBody, class SecondObserver>
struct angular_velocities_do_not_chain_the_first_body_must_be_the_second_observer {};
// ^A v^P + ^B v^Q: measure both in one frame first, velocity<A, Q>().
template <class FirstObserver, class SecondObserver>
struct quantities_measured_in_different_frames_measure_both_in_one_frame {};
// dt(v) of a vector: its derivative depends on the frame; write dt<A>(v).
template <class Vector>
struct a_vector_derivative_needs_a_frame_write_dt_A_of_v {};
template <class Vector>
struct a_vector_derivative_needs_a_frame_write_diff_A_of_v_q {};
// partial_velocity(v, q<1>): partial velocities are d/du_r; pass u<r>.
template <class NotASpeed>
struct partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r {};
}  // namespace error

}  // namespace kane
