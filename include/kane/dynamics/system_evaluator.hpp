// The state and the evaluator a system implies: its coordinates, speeds, parameters and inputs
// counted from the types of its items, and the frames its bodies, points and loads read.
//
//   using state = kane::state_of<System>;                   // state<double, nq, nu, np, nr>
//   using state2 = kane::state_of<System, Speeds, float>;   // with a speed set, in float
//   kane::system_evaluator<System, Speeds> ev;              // level::acceleration
//   ev.update(s);
//
// With a speed set nq is the number of its kinematic equations and nu its number of speeds;
// without one nq is the highest q_i read, and u = q'. np and nr are the highest p_i and r_i read.
#pragma once

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/loads.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/evaluation/expression_reads.hpp"
#include "kane/evaluation/state_indices.hpp"
#include "kane/frames/state.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// What an item reads beyond its expressions: the inertia's components.
template <class X>
constexpr highest highest_of_item() {
  if constexpr (is_body<X>)
    return highest_in_tuple<std::remove_cvref_t<decltype(X::inertia_type::components)>>();
  else
    return {};
}
template <class... X>
constexpr highest highest_of_items(list<X...>) {
  highest h;
  (h.take(highest_of_item<X>()), ...);
  return h;
}
template <class... X>
constexpr highest highest_of_list(list<X...>) {
  highest h;
  (h.take(highest_in<std::remove_cvref_t<X>>()), ...);
  return h;
}

// Each type once, in the order first met: a flat fold, however long the list.
template <class... A, class T>
constexpr auto operator|(list<A...>, std::type_identity<T>) {
  if constexpr ((std::is_same_v<A, T> || ...))
    return list<A...>{};
  else
    return list<A..., T>{};
}
template <class... T>
constexpr auto each_once(list<T...>) {
  return (list<>{} | ... | std::type_identity<T>{});
}

// The expressions an item is made of: the positions along its point's chain (a point known by
// its velocity: that velocity), its mass, its load's vector. Velocities, accelerations and partial
// velocities derive from them and the frames' edges, and read no other frame or number.
template <class Q>
constexpr auto point_expression() {
  if constexpr (requires { Q::known_velocity; })
    return Q::known_velocity;
  else
    return Q::position;
}
template <class... Q>
constexpr auto chain_expressions(list<Q...>) {
  return list<decltype(point_expression<Q>())...>{};
}
template <class X>
constexpr auto item_expressions() {
  if constexpr (is_particle<X> || is_body<X>)
    return typename concat<decltype(chain_expressions(
                               typename point_chain<typename point_of_mass<X>::type>::type{})),
                           list<std::remove_cvref_t<decltype(X::mass)>>>::type{};
  else if constexpr (is_force<X>)
    return typename concat<decltype(chain_expressions(typename point_chain<typename X::point>::type{})),
                           list<std::remove_cvref_t<decltype(X::vector)>>>::type{};
  else if constexpr (is_torque<X> || is_gravity<X>)
    return list<std::remove_cvref_t<decltype(X::vector)>>{};
  else
    return list<>{};
}

// The frames the items of a system read (the bodies' and torques' frames, the inertias' frames,
// the frames of their expressions and of the expressions More), ancestors first, no root.
template <class Sys, class More = list<>>
struct system_frames {
  template <class... X>
  static auto turning(list<X...>) -> typename concat<typename turning_frames<X>::type...>::type;
  template <class... X>
  static auto made_of(list<X...>) -> typename concat<decltype(item_expressions<X>())...>::type;
  template <class... T>
  static auto read(list<T...>) -> typename concat<decltype(frames_read<std::remove_cvref_t<T>>())...>::type;
  template <class... F>
  static auto all(list<F...>) -> typename closure<F...>::type;
  template <class... F>
  static auto held(list<F...>) -> typename concat<held_frames<F>...>::type;

  using expressions = typename concat<decltype(made_of(typename Sys::items{})), More>::type;
  using closed = decltype(all(each_once(
      typename concat<decltype(turning(typename Sys::items{})), decltype(read(expressions{}))>::type{})));
  using type = decltype(held(closed{}));
};

// The numbers of a system's state.
template <class Sys, class Sp, class More = list<>>
constexpr highest system_sizes() {
  using F = system_frames<Sys, More>;
  highest h = highest_of_list(typename F::expressions{});
  h.take(highest_of_items(typename Sys::items{}));
  h.take(highest_of_edges(typename F::closed{}));
  if constexpr (std::is_void_v<Sp>)
    h.u = h.q;
  else {
    if constexpr (requires { Sp::definitions; })
      h.take(highest_in_tuple<std::remove_cvref_t<decltype(Sp::definitions)>>());
    h.q = Sp::rows, h.u = Sp::n;
  }
  return h;
}
// The evaluator of Sys with the frames that the expressions More also read.
template <class Sys, class Sp, level L, class St, class More = list<>>
using evaluator_reading =
    evaluator<St, typename as_frames<typename system_frames<Sys, More>::type>::type, L, Sp>;
}  // namespace detail

// The state of a system: state<S, nq, nu, np, nr>, the numbers read by its items (and Speeds).
// (More: expressions read beside the items', such as constraints; internal.)
template <System Sys, class Speeds = void, class S = double, class More = detail::list<>>
using state_of =
    state<S, detail::system_sizes<Sys, Speeds, More>().q, detail::system_sizes<Sys, Speeds, More>().u,
          detail::system_sizes<Sys, Speeds, More>().p, detail::system_sizes<Sys, Speeds, More>().r>;

// The evaluator of a system: the frames its items read, at level L, with Speeds, of a state St.
template <System Sys, class Speeds = void, level L = level::acceleration, State St = state_of<Sys, Speeds>>
using system_evaluator = detail::evaluator_reading<Sys, Speeds, L, St>;

namespace detail {
// X itself where it is an evaluator, else the system's evaluator with the speed set X (none: u = q').
template <class Sys, class X, level L = level::acceleration, class More = list<>, class S = double>
constexpr auto evaluator_or_own() {
  if constexpr (is_evaluator<X>::value) {
    static_assert(std::is_same_v<S, double> || std::is_same_v<S, typename X::scalar>,
                  "kane: an evaluator brings its scalar: name it in the evaluator's state, not here");
    return std::type_identity<X>{};
  } else {
    static_assert(std::is_void_v<X> || SpeedSet<X>,
                  "kane: the second argument is an evaluator (kane::evaluator<...>) or a speed set "
                  "(kane::speeds<...>), or none");
    // x holds u = q' in full: the speed set of q' reads it without asking s.qd (evaluator.hpp)
    using Sp = std::conditional_t<SpeedSet<X>, X, qdot_speeds<system_sizes<Sys, void, More>().q>>;
    return std::type_identity<evaluator_reading<Sys, Sp, L, state_of<Sys, Sp, S, More>, More>>{};
  }
}
template <class Sys, class X, level L = level::acceleration, class More = list<>>
using evaluator_or_own_t = typename decltype(evaluator_or_own<Sys, X, L, More>())::type;
// The evaluator E where E is one, else the system's own (speed set X) over the scalar E.
template <class Sys, class X, class E, class More = list<>>
using own_evaluator_t = typename std::conditional_t<
    is_evaluator<E>::value, std::type_identity<E>,
    decltype(evaluator_or_own<Sys, X, level::acceleration, More,
                              std::conditional_t<is_evaluator<E>::value, double, E>>())>::type;
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
