// The loads that turn with the bodies they act on, for the analytical derivatives
// (rnea_derivatives.hpp): their components in a frame fixed in that body are literals,
// constants, parameters and inputs, so a change of q turns them with the body.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/list.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/joint_form.hpp"
#include "kane/dynamics/detail/tree/turns.hpp"
#include "kane/expressions/known_values.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// A load keeps its components in the frame of the body it acts on: literals, constants,
// parameters and inputs times unit vectors of a frame fixed in that body.
template <class X>
constexpr bool steady_scalar() {
  if constexpr (known_scalar<X>() || Parameter<X> || Input<X>)
    return true;
  else if constexpr (is_v<X, add> || is_v<X, sub> || is_v<X, mul> || is_v<X, quot>)
    return steady_scalar<std::remove_cv_t<decltype(std::declval<const X&>().l)>>() &&
           steady_scalar<std::remove_cv_t<decltype(std::declval<const X&>().r)>>();
  else if constexpr (is_v<X, neg>)
    return steady_scalar<std::remove_cv_t<decltype(std::declval<const X&>().x)>>();
  else
    return false;
}
// The frame of the nearest edge at or above f that a speed or the free joint turns (0: the root).
template <class T>
constexpr int body_of(const T& t, int f) {
  while (f > 0 && t.speed[std::size_t(f)] < 0 && f != t.free) f = t.parent[std::size_t(f)];
  return f < 0 ? 0 : f;
}
// The coordinate axis each frame's edge turns about (-1: none or another).
template <class JF>
inline constexpr auto edge_axes = []<class... F>(list<F...>) {
  return std::array<int, sizeof...(F)>{turn_axis<F>()...};
}(typename JF::frame_list{});
// e<G, I> is fixed in the body of frame `body`: G is, or an edge above G turns about e<G, I>, or
// every edge from `body` up to G does (a joint's torque along its axis in the parent's components).
template <class JF, class G, int I>
constexpr bool unit_fixed_in(int body) {
  constexpr int g = index_in<G>(typename JF::frame_list{});
  if (g >= 0 && body_of(JF::table, g) == body) return true;
  int h = body;
  while (h > 0 && h != g && edge_axes<JF>[std::size_t(h)] == I - 1) h = JF::table.parent[std::size_t(h)];
  if (g >= 0 && h == g) return true;
  if constexpr (!std::is_void_v<typename G::tree_parent> && turn_axis<G>() == I - 1)
    return unit_fixed_in<JF, typename G::tree_parent, I>(body);
  else
    return false;
}
// V: steady scalars times unit vectors of frames fixed in the body of frame `body`.
template <class JF, class V>
constexpr bool steady_vector(int body) {
  if constexpr (is_zero_vector_v<V>)
    return true;
  else if constexpr (is_unit<V>::value)
    return unit_fixed_in<JF, typename V::frame, V::index>(body);
  else if constexpr (is_v<V, scaled>)
    return steady_scalar<std::remove_cv_t<decltype(std::declval<const V&>().s)>>() &&
           steady_vector<JF, std::remove_cv_t<decltype(std::declval<const V&>().v)>>(body);
  else if constexpr (is_v<V, vneg>)
    return steady_vector<JF, std::remove_cv_t<decltype(std::declval<const V&>().v)>>(body);
  else if constexpr (is_v<V, vsum> || is_v<V, vdiff>)
    return steady_vector<JF, std::remove_cv_t<decltype(std::declval<const V&>().l)>>(body) &&
           steady_vector<JF, std::remove_cv_t<decltype(std::declval<const V&>().r)>>(body);
  else
    return false;
}
template <class JF, class X, std::size_t I>
constexpr bool steady_load() {
  if constexpr (!is_force<X> && !is_torque<X>)
    return true;
  else
    return steady_vector<JF, std::remove_cv_t<decltype(X::vector)>>(
        body_of(JF::table, JF::table.item_frame[I]));
}
template <class JF, class... X, std::size_t... I>
constexpr bool steady_loads(list<X...>, std::index_sequence<I...>) {
  return (steady_load<JF, X, I>() && ...);
}
template <class Sys, class JF>
inline constexpr bool steady_loads_of =
    steady_loads<JF>(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});

}  // namespace kane::detail
#pragma GCC diagnostic pop
