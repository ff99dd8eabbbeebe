// What the tree says of the edge above a frame F at compile time: which numbers
// of F's axes in the root are 0 or 1 at every state (detail/patterned.hpp), and
// theta' and theta'' as expressions.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "kane/detail/patterned.hpp"
#include "kane/expressions/direction_cosines.hpp"
#include "kane/frames/axis.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class F>
constexpr bool below_root() {
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return false;
  else
    return std::is_void_v<typename F::tree_parent::tree_parent>;
}

// e_F1, e_F2, e_F3 in the root, column after column: a turn about a principal axis keeps one of
// the parent's columns and mixes the other two.
template <class F>
constexpr std::array<entry, 9> column_pattern() {
  using enum entry;
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return {one, zero, zero, zero, one, zero, zero, zero, one};
  else if constexpr (!spin_edge<F> && !matrix_edge<F> && edge_principal<F>() >= 0)
    return turned_columns(column_pattern<typename F::tree_parent>(), edge_principal<F>());
  else
    return {other, other, other, other, other, other, other, other, other};
}

// The axis k of the edge above F in the root: constant below the root, else a column of the parent.
template <class F>
constexpr std::array<entry, 3> axis_pattern() {
  constexpr auto k = unit_axis<typename F::step::axis>::value;
  constexpr int p = unit_axis<typename F::step::axis>::principal;
  if constexpr (below_root<F>())
    return {entry_of_number(k[0]), entry_of_number(k[1]), entry_of_number(k[2])};
  else if constexpr (p >= 0) {
    constexpr auto pp = column_pattern<typename F::tree_parent>();
    return {pp[std::size_t(3 * p)], pp[std::size_t(3 * p + 1)], pp[std::size_t(3 * p + 2)]};
  } else
    return {entry::other, entry::other, entry::other};
}

// theta^(D) of the edge above F: q^(D) for a bare coordinate, else dt^D(theta); u and u' for a spin.
template <class F, std::size_t D>
constexpr auto angle_rate() {
  if constexpr (spin_edge<F>)
    return speed<F::step::speed_index, D - 1>{};
  else if constexpr (D == 1)
    return ddt(F::step::angle);
  else
    return ddt(ddt(F::step::angle));
}
template <class F, std::size_t D>
inline constexpr bool turns = !std::is_same_v<std::remove_cv_t<decltype(angle_rate<F, D>())>, zero_t>;

}  // namespace kane::detail
#pragma GCC diagnostic pop
