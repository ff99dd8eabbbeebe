// What expressions read of an evaluator, found from their types: the frames an evaluator must hold
// for them and the level it must compute (kane::reads), and what a table of partial velocities reads
// (kane::partials_of). evaluator_for.hpp holds their values.
//
//   using r = kane::reads<v, a, kane::partials_of(v)>;
//   r::frames   // kane::frames<...>: the frames v, a and v_r read
//   r::needed   // kane::level::acceleration: a reads angular accelerations
//
// A unit vector needs the highest frame it is a unit vector of (e_B3 = e_A3 when B turns
// about a3), an angular velocity or acceleration of a frame turned by one axis its parent only
// (outward_pass.hpp: one edge below a held frame); q', u or an angular velocity ask for
// level::velocity, q'', u' or an angular acceleration for level::acceleration.
#pragma once

#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/evaluation/outward_pass.hpp"
#include "kane/expressions/direction_cosines.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative_traits.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// What the partial velocities of x read (partial_velocities, nonholonomic_partial_velocities,
// solve_constraints of x): x's frames at the pose level, the speeds' W and X with them.
template <class X>
struct partials_of_t {
  X x;
};
template <class X>
constexpr partials_of_t<X> partials_of(X x) {
  static_assert(VectorExpr<X> || ScalarExpr<X>,
                "kane: partials_of takes an expression linear in the speeds; for a frame pass its angular "
                "velocity, kane::angular_velocity<N, F>()");
  return {x};
}

namespace detail {
// The frame an evaluator holds for omega<F> or alpha<F>: F's parent where F turns about one axis.
template <class F>
using rates_frame = std::conditional_t<matrix_edge<F> || spin_edge<F>, F, typename F::tree_parent>;
template <class F>
using held_frames = std::conditional_t<std::is_void_v<typename F::tree_parent>, list<>, list<F>>;

template <class X>
constexpr auto frames_read() {
  using C = const X&;
  if constexpr (is_unit<X>::value)
    return held_frames<lifted_t<typename X::frame, X::index>>{};
  else if constexpr (is_v<X, omega> || is_v<X, alpha>)
    return held_frames<rates_frame<typename X::frame>>{};
  else if constexpr (is_v<X, angular_velocity_of> || is_v<X, angular_acceleration_of>)
    return frames_read<decltype(expand(std::declval<C>()))>();
  else if constexpr (requires(C x) {
                       x.l;
                       x.r;
                     })
    return
        typename concat<decltype(frames_read<std::remove_cvref_t<decltype(std::declval<C>().l)>>()),
                        decltype(frames_read<std::remove_cvref_t<decltype(std::declval<C>().r)>>())>::type{};
  else if constexpr (requires(C x) {
                       x.s;
                       x.v;
                     })
    return
        typename concat<decltype(frames_read<std::remove_cvref_t<decltype(std::declval<C>().s)>>()),
                        decltype(frames_read<std::remove_cvref_t<decltype(std::declval<C>().v)>>())>::type{};
  else if constexpr (requires(C x) { x.v; })
    return frames_read<std::remove_cvref_t<decltype(std::declval<C>().v)>>();
  else if constexpr (requires(C x) { x.x; })
    return frames_read<std::remove_cvref_t<decltype(std::declval<C>().x)>>();
  else
    return list<>{};
}
// 0 pose, 1 velocity, 2 acceleration
template <class X>
constexpr int level_read() {
  using C = const X&;
  if constexpr (is_v<X, partials_of_t>)
    return 0;
  else if constexpr (is_v<X, omega>)
    return 1;
  else if constexpr (is_v<X, alpha>)
    return 2;
  else if constexpr (coordinate_info<X>::value)
    return int(X::order);
  else if constexpr (speed_info<X>::value)
    return int(X::order) + 1;
  else if constexpr (is_v<X, angular_velocity_of> || is_v<X, angular_acceleration_of>)
    return level_read<decltype(expand(std::declval<C>()))>();
  else if constexpr (requires(C x) {
                       x.l;
                       x.r;
                     }) {
    constexpr int a = level_read<std::remove_cvref_t<decltype(std::declval<C>().l)>>(),
                  b = level_read<std::remove_cvref_t<decltype(std::declval<C>().r)>>();
    return a > b ? a : b;
  } else if constexpr (requires(C x) {
                         x.s;
                         x.v;
                       }) {
    constexpr int a = level_read<std::remove_cvref_t<decltype(std::declval<C>().s)>>(),
                  b = level_read<std::remove_cvref_t<decltype(std::declval<C>().v)>>();
    return a > b ? a : b;
  } else if constexpr (requires(C x) { x.v; })
    return level_read<std::remove_cvref_t<decltype(std::declval<C>().v)>>();
  else if constexpr (requires(C x) { x.x; })
    return level_read<std::remove_cvref_t<decltype(std::declval<C>().x)>>();
  else
    return 0;
}
template <class L>
struct as_frames;
template <class... F>
struct as_frames<list<F...>> {
  using type = frames<F...>;
};
}  // namespace detail

// The expressions an evaluator is for (evaluator_for).
template <auto... X>
struct reads {
  // the frames the expressions read, each once
  using frames = typename detail::as_frames<typename detail::unique<typename detail::concat<
      decltype(detail::frames_read<std::remove_cvref_t<decltype(X)>>())...>::type>::type>::type;
  static_assert(!std::is_same_v<frames, kane::frames<>>,
                "kane: these expressions read no frame but a root; hold one with kane::evaluator<State, "
                "kane::frames<F>>");
  // the lowest level that evaluates them all
  static constexpr level needed = [] {
    int l = 0;
    ((l = detail::level_read<std::remove_cvref_t<decltype(X)>>() > l
              ? detail::level_read<std::remove_cvref_t<decltype(X)>>()
              : l),
     ...);
    return l == 0 ? level::pose : l == 1 ? level::velocity : level::acceleration;
  }();
};

}  // namespace kane
#pragma GCC diagnostic pop
