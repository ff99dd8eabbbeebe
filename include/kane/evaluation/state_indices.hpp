// The highest q_i, u_i, p_i and r_i that an expression or the edges of frames read: the sizes of
// the state they need (kane::state_of, and the evaluator's check of its state).
#pragma once

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/list.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative_traits.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/coordinate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The highest q_i, u_i, p_i and r_i an expression reads (0: none).
struct highest {
  std::size_t q = 0, u = 0, p = 0, r = 0;
  constexpr void take(const highest& o) {
    q = std::max(q, o.q), u = std::max(u, o.u), p = std::max(p, o.p), r = std::max(r, o.r);
  }
};
template <class X>
constexpr highest highest_in() {
  using C = const X&;
  highest h;
  if constexpr (coordinate_info<X>::value)
    h.q = X::index;
  else if constexpr (speed_info<X>::value)
    h.u = X::index;
  else if constexpr (Parameter<X>)
    h.p = X::index;
  else if constexpr (Input<X>)
    h.r = X::index;
  else if constexpr (is_v<X, angular_velocity_of> || is_v<X, angular_acceleration_of>)
    h = highest_in<decltype(expand(std::declval<C>()))>();
  else if constexpr (requires(C x) {
                       x.l;
                       x.r;
                     }) {
    h = highest_in<std::remove_cvref_t<decltype(std::declval<C>().l)>>();
    h.take(highest_in<std::remove_cvref_t<decltype(std::declval<C>().r)>>());
  } else if constexpr (requires(C x) {
                         x.s;
                         x.v;
                       }) {
    h = highest_in<std::remove_cvref_t<decltype(std::declval<C>().s)>>();
    h.take(highest_in<std::remove_cvref_t<decltype(std::declval<C>().v)>>());
  } else if constexpr (requires(C x) { x.v; })
    h = highest_in<std::remove_cvref_t<decltype(std::declval<C>().v)>>();
  else if constexpr (requires(C x) { x.x; })
    h = highest_in<std::remove_cvref_t<decltype(std::declval<C>().x)>>();
  return h;
}
template <class T>
constexpr highest highest_in_tuple() {
  highest h;
  [&]<std::size_t... K>(std::index_sequence<K...>) {
    (h.take(highest_in<std::remove_cvref_t<std::tuple_element_t<K, T>>>()), ...);
  }
  (std::make_index_sequence<std::tuple_size_v<T>>{});
  return h;
}
// What the edge above F reads: an angle, four Euler parameters, a spin's speed, an attitude's
// parameters and speeds.
template <class F>
constexpr highest highest_of_edge() {
  highest h;
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return h;
  else if constexpr (spin_edge<F>)
    h.u = F::step::speed_index;
  else if constexpr (attitude_edge<F>) {
    h.p = F::step::source::first + F::step::source::count - 1;
    for (std::size_t r : F::step::rate_speeds) h.u = std::max(h.u, r);
  } else if constexpr (euler_edge<F>) {
    for (std::size_t i : F::step::coordinates) h.q = std::max(h.q, i);
  } else if constexpr (requires { F::step::angle; })
    h = highest_in<std::remove_cvref_t<decltype(F::step::angle)>>();
  return h;
}
template <class... F>
constexpr highest highest_of_edges(list<F...>) {
  highest h;
  (h.take(highest_of_edge<F>()), ...);
  return h;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
