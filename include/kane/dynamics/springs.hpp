// A linear spring between two points, declared with the loads:
//
//   kane::spring<P, Q, k, L>   stiffness k, free length L, r = r^PQ, s = |r| - L:
//                              the force -k s r / |r| on Q and its opposite on P (none on a point
//                              fixed in a root frame, where it does no work); V = k s^2 / 2
//
// A spring is a system of its two forces and its energy (dynamics/momenta.hpp, potential_energy).
#pragma once

#include <type_traits>

#include "kane/detail/list.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/point.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// k s^2 / 2 of a spring: an item that is neither a mass nor a load.
template <auto V>
struct spring_energy {
  static constexpr bool well_formed = true;
  static constexpr auto energy = V;
};
template <class X>
inline constexpr bool is_spring_energy = requires {
  X::energy;
};

// P is at rest in a root frame: on a chain from an origin of a root frame, fixed in it.
template <class P>
constexpr bool at_rest_in_a_root() {
  using O = chain_root_t<P>;
  if constexpr (std::is_void_v<typename O::fixed_frame>)
    return false;
  else
    return std::is_void_v<typename O::fixed_frame::tree_parent> && fixed_in<P, typename O::fixed_frame>();
}
}  // namespace detail

namespace detail {
template <class P, class Q, auto K, auto L, bool Scalars>
struct spring_items {
  using type = list<>;
};
template <class P, class Q, auto K, auto L>
struct spring_items<P, Q, K, L, true> {
  static constexpr auto r = position<P, Q>();
  static constexpr auto stretch = sqrt(dot(r, r)) - L;
  static constexpr auto pull = freeze<K * stretch * normalized(r)>();  // on P, towards Q
  using energy = spring_energy<constant<1, 2>{} * K * stretch * stretch>;
  using type = std::conditional_t<at_rest_in_a_root<P>(), list<force<Q, -pull>, energy>,
                                  list<force<Q, -pull>, force<P, pull>, energy>>;
};
}  // namespace detail

// A linear spring between P and Q: stiffness K, free length L.
template <Point P, Point Q, auto K, auto L>
struct spring : detail::system_tag {
  // K and L are scalar expressions
  static constexpr bool scalars = ScalarExpr<decltype(K)> && ScalarExpr<decltype(L)>;
  static_assert(scalars,
                "kane: spring<P, Q, k, L> takes scalar expressions k (stiffness) and L (free length)");
  // the spring keeps its rules (a system admits it only then)
  static constexpr bool well_formed = scalars;
  // the pulls on Q and P (none on a P at rest in a root) and the energy k s^2 / 2
  using items = typename detail::spring_items<P, Q, K, L, scalars>::type;
};

}  // namespace kane
#pragma GCC diagnostic pop
