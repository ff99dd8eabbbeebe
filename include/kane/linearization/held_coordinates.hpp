// The coordinates whose values the equations of motion read: through a frame of
// the evaluator that turns by them, a definition of the speeds, or an expression
// of the system, its nonholonomic or holonomic constraints. The partial
// derivatives by any other coordinate are zero at every state (a bicycle's or a
// disc's contact position): linearize gives them no jet direction.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/list.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

using coordinate_mask = std::uint64_t;  // bit I - 1: q_I
inline constexpr coordinate_mask every_coordinate = ~coordinate_mask(0);

template <class... X>
constexpr coordinate_mask coordinates_in(list<X...>);
// The coordinate values an expression reads (frames apart: units, w and alpha are leaves here).
template <class X>
constexpr coordinate_mask coordinates_in() {
  if constexpr (coordinate_info<X>::value) {
    if constexpr (X::order != 0)
      return 0;  // a rate: the speeds' business
    else
      return X::index <= 64 ? coordinate_mask(1) << (X::index - 1) : every_coordinate;
  } else
    return coordinates_in(children_t<X>{});
}
template <class... X>
constexpr coordinate_mask coordinates_in(list<X...>) {
  return (coordinate_mask(0) | ... | coordinates_in<std::remove_cvref_t<X>>());
}
template <class T>
constexpr coordinate_mask coordinates_in_tuple() {
  return []<std::size_t... K>(std::index_sequence<K...>) {
    return (coordinate_mask(0) | ... | coordinates_in<std::remove_cvref_t<std::tuple_element_t<K, T>>>());
  }
  (std::make_index_sequence<std::tuple_size_v<T>>{});
}

// The coordinates the edge above F turns by (a root: none).
template <class F>
constexpr coordinate_mask edge_coordinates() {
  if constexpr (std::is_void_v<typename F::tree_parent> || spin_edge<F> || attitude_edge<F>)
    return 0;  // a spin turns at a speed; an attitude is read from parameters
  else if constexpr (euler_edge<F>) {
    coordinate_mask m = 0;
    for (std::size_t i : F::step::coordinates)
      m |= i <= 64 ? coordinate_mask(1) << (i - 1) : every_coordinate;
    return m;
  } else if constexpr (requires { F::step::angle; })
    return coordinates_in<std::remove_cvref_t<decltype(F::step::angle)>>();
  else
    return every_coordinate;
}
template <class... F>
constexpr coordinate_mask frame_coordinates(list<F...>) {
  return (coordinate_mask(0) | ... | edge_coordinates<F>());
}

template <class Sp>
constexpr coordinate_mask speed_coordinates() {
  if constexpr (std::is_void_v<Sp>)
    return 0;
  else if constexpr (Sp::identity)
    return 0;
  else if constexpr (requires { Sp::definitions; })
    return coordinates_in_tuple<std::remove_cvref_t<decltype(Sp::definitions)>>();
  else
    return every_coordinate;
}

// The coordinates by which a holonomic constraint of H has a partial derivative not zero at
// compile time (q1 n1 . n3 holds q1, but not its derivative).
template <class H, std::size_t NQ>
constexpr coordinate_mask partials_held() {
  coordinate_mask m = NQ > 64 ? every_coordinate : 0;
  static_for<(NQ < 64 ? NQ : 64)>([&](auto i) {
    static_for<H::m>([&](auto k) {
      if constexpr (!is_zero_v<
                        std::remove_cvref_t<decltype(diff(std::get<k>(H::equations), coordinate<i + 1>{}))>>)
        m |= coordinate_mask(1) << i;
    });
  });
  return m;
}

// What the right-hand side of Sys with constraints NH and H (void: none) reads, evaluated by Ev.
template <class Sys, class NH, class Ev, class H>
constexpr coordinate_mask coordinates_held() {
  using R = typename Ev::root;
  coordinate_mask m = frame_coordinates(typename Ev::closure{}) |
                      speed_coordinates<typename Ev::speed_set>() |
                      coordinates_in(decltype(system_terms<R, speeds_of<Ev>>(typename Sys::items{})){});
  if constexpr (!std::is_void_v<NH>)
    m |= coordinates_in_tuple<std::remove_cvref_t<decltype(NH::equations)>>();
  if constexpr (!std::is_void_v<H>) m |= partials_held<H, Ev::state_type::nq>();
  return m;
}

// A jet direction for each coordinate of Qi that is held (slot[k]), none for the others.
inline constexpr std::size_t no_slot = ~std::size_t(0);
template <auto Qi, coordinate_mask Held>
constexpr auto coordinate_slots() {
  struct slots {
    std::array<std::size_t, Qi.size()> slot{};
    std::size_t n = 0;
  } out;
  for (std::size_t k = 0; k < Qi.size(); ++k)
    out.slot[k] = Qi[k] > 64 || ((Held >> (Qi[k] - 1)) & 1) ? out.n++ : no_slot;
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
