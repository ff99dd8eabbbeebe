// What acts on the masses of a system:
//
//   kane::force<P, R>    R (a vector expression) applied at the point P
//   kane::torque<B, T>   a couple of torque T on the frame B
//   kane::gravity<g>     m g at every particle and mass centre
//
// Loads are vector expressions of q, u, t, inputs and parameters.
#pragma once

#include <concepts>
#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/point.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct load_tag {};
}  // namespace detail

// A force R (a vector expression) applied at the point P.
template <Point P, auto R>
struct force : detail::load_tag {
  static_assert(VectorExpr<decltype(R)>, "kane: force<P, R> takes a vector expression R");
  // P, the point of application
  using point = P;
  // R, the force
  static constexpr auto vector = detail::freeze<R>();
};
// A torque T (a vector expression) applied to the frame B.
template <Frame B, auto T>
struct torque : detail::load_tag {
  static_assert(VectorExpr<decltype(T)>, "kane: torque<B, T> takes a vector expression T");
  // the frame trees of T and B, joined
  using trees = detail::join_trees_t<detail::tree_of_t<std::remove_cvref_t<decltype(T)>>, detail::root_of<B>>;
  static_assert(detail::one_tree_v<trees>);
  // T is a vector expression and B, T share one tree
  static constexpr bool well_formed = VectorExpr<decltype(T)> && !detail::is_two_roots_v<trees>;
  // B, the frame the torque acts on
  using frame = B;
  // T, the torque
  static constexpr auto vector = detail::freeze<T>();
};
// Gravity G on every particle and mass centre of the system.
template <auto G>
struct gravity : detail::load_tag {
  static_assert(VectorExpr<decltype(G)>, "kane: gravity<g> takes a vector expression g");
  // G, the acceleration of gravity
  static constexpr auto vector = detail::freeze<G>();
};

namespace detail {
template <class T>
inline constexpr bool is_force = requires {
  typename T::point;
}
&&std::derived_from<T, load_tag>;
template <class T>
inline constexpr bool is_torque = requires {
  typename T::frame;
}
&&std::derived_from<T, load_tag>;
template <class T>
inline constexpr bool is_gravity = std::derived_from<T, load_tag> && !is_force<T> && !is_torque<T>;
// g, the sum of the gravity loads among X (zero_vector without one).
template <class... X>
constexpr auto gravity_of(list<X...>) {
  return (zero_vector{} + ... + [] {
    if constexpr (is_gravity<X>)
      return X::vector;
    else
      return zero_vector{};
  }());
}
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
