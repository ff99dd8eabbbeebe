// Vectors fixed in one frame (the position vectors of points in a system of joint
// form, joint_form.hpp): the frame and their components in it. Which of those are 0 or 1
// at every state, and their values where known at compile time: expressions/known_values.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/patterned.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/expressions/known_values.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

struct no_frame {};     // the zero vector: fixed in every frame
struct mixed_frame {};  // fixed in no one frame (or not constant)

template <class S>
inline constexpr bool constant_scalar =
    std::is_same_v<std::remove_cv_t<decltype(ddt(std::declval<S>()))>, zero_t>;

// The frame a vector expression is fixed in: sums of constants times unit vectors of one frame.
template <class V>
struct fixed_frame_of {
  using type = mixed_frame;
};
template <>
struct fixed_frame_of<zero_vector> {
  using type = no_frame;
};
template <class F, int I>
struct fixed_frame_of<unit<F, I>> {
  using type = F;
};
template <class S, class V>
struct fixed_frame_of<scaled<S, V>> {
  using type = std::conditional_t<constant_scalar<S>, typename fixed_frame_of<V>::type, mixed_frame>;
};
template <class V>
struct fixed_frame_of<vneg<V>> : fixed_frame_of<V> {};
template <class A, class B>
struct joined_fixed_frame {
  using type = std::conditional_t<
      std::is_same_v<A, no_frame>, B,
      std::conditional_t<std::is_same_v<B, no_frame> || std::is_same_v<A, B>, A, mixed_frame>>;
};
template <class L, class R>
struct fixed_frame_of<vsum<L, R>>
    : joined_fixed_frame<typename fixed_frame_of<L>::type, typename fixed_frame_of<R>::type> {};
template <class L, class R>
struct fixed_frame_of<vdiff<L, R>>
    : joined_fixed_frame<typename fixed_frame_of<L>::type, typename fixed_frame_of<R>::type> {};

// The components of a vector fixed in its frame (fixed_frame_of), in that frame.
template <class V, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> own_components(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (is_zero_vector_v<V>)
    return {S(0), S(0), S(0)};
  else if constexpr (is_unit<V>::value)
    return {S(V::index == 1), S(V::index == 2), S(V::index == 3)};
  else if constexpr (is_v<V, scaled>)
    return S(eval_scalar(v.s, ev)) * own_components(v.v, ev);
  else if constexpr (is_v<V, vsum>)
    return own_components(v.l, ev) + own_components(v.r, ev);
  else if constexpr (is_v<V, vdiff>)
    return own_components(v.l, ev) - own_components(v.r, ev);
  else
    return -own_components(v.v, ev);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
