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
}  // namespace error

}  // namespace kane
