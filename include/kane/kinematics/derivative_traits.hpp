// What derivatives need to know of expressions: the frame and root a vector uses, and which
// rates q' and speeds u an expression holds (so a derivative by another one is zero without being
// built). The kinds of nodes and freeze: expressions/nodes.hpp. The edges of the tree:
// kinematics/edges.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>

#include "kane/detail/choices.hpp"
#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/expressions/nodes.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

// A frame that the vector V uses (void if none): its root is V's root.
template <class V>
struct some_frame {
  using type = void;
};
template <class F, int I>
struct some_frame<unit<F, I>> {
  using type = F;
};
template <class F>
struct some_frame<omega<F>> {
  using type = F;
};
template <class F>
struct some_frame<alpha<F>> {
  using type = F;
};
template <class A, class B>
struct some_frame<angular_velocity_of<A, B>> {
  using type = A;
};
template <class A, class B>
struct some_frame<angular_acceleration_of<A, B>> {
  using type = A;
};
template <class S, class V>
struct some_frame<scaled<S, V>> : some_frame<V> {};
template <class V>
struct some_frame<vneg<V>> : some_frame<V> {};
template <template <class, class> class T, class L, class R>
requires(is_v<T<L, R>, vsum> || is_v<T<L, R>, vdiff> || is_v<T<L, R>, vcross>) struct some_frame<T<L, R>> {
  using type = std::conditional_t<std::is_void_v<typename some_frame<L>::type>, typename some_frame<R>::type,
                                  typename some_frame<L>::type>;
};

template <class V>
constexpr auto root_frame_of() {
  using F = typename some_frame<V>::type;
  if constexpr (std::is_void_v<F>)
    return static_cast<root_frame*>(nullptr);
  else
    return static_cast<root_of<F>*>(nullptr);
}
template <class V>
using root_frame_of_t = std::remove_pointer_t<decltype(root_frame_of<V>())>;

// The rates q_i' and speeds u_i that an expression may hold (bit i - 1; all
// bits for an index beyond 64 or a node not listed): the partial derivative
// by a rate or speed outside the set is zero (sums and products drop the
// type-level zeros), so it is returned without being built.
struct leaf_set {
  std::uint64_t rates = 0, speeds = 0;
  bool all = false;  // a query that every expression may hold (a leaf other than q' or u)
};
constexpr leaf_set operator|(leaf_set a, leaf_set b) {
  return {a.rates | b.rates, a.speeds | b.speeds, a.all || b.all};
}
constexpr bool overlaps(leaf_set x, leaf_set leaf) {
  return leaf.all || (x.rates & leaf.rates) != 0 || (x.speeds & leaf.speeds) != 0;
}
constexpr std::uint64_t leaf_bit(std::size_t i) {
  return i >= 1 && i <= 64 ? std::uint64_t(1) << (i - 1) : ~std::uint64_t(0);
}
inline constexpr leaf_set any_leaf{~std::uint64_t(0), ~std::uint64_t(0)};
template <class X>
constexpr leaf_set leaves_in();
template <class X>
inline constexpr leaf_set leaves_of = leaves_in<X>();  // once per node type
// The rates of the edge above F, and of the edges from the root down to F (those of ^R w^F).
template <class F>
constexpr std::uint64_t edge_rates() {
  if constexpr (spin_edge<F> || attitude_edge<F>)
    return 0;
  else if constexpr (euler_edge<F>) {
    constexpr auto c = F::step::coordinates;
    return leaf_bit(c[0]) | leaf_bit(c[1]) | leaf_bit(c[2]) | leaf_bit(c[3]);
  } else
    return leaves_of<decltype(ddt(F::step::angle))>.rates;
}
// The rates q' or the speeds u of ^R w^F, R the root.
template <class F, wrt By = wrt::rates>
constexpr std::uint64_t path_rates() {
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return 0;
  else if constexpr (By == wrt::speeds)
    return [] {
      std::uint64_t bits = 0;
      for (std::size_t i : free_speeds<F>())
        if (i != 0) bits |= leaf_bit(i);
      return bits;
    }() | path_rates<typename F::tree_parent, wrt::speeds>();
  else
    return edge_rates<F>() | path_rates<typename F::tree_parent>();
}
template <class... F>
constexpr leaf_set omega_leaves() {
  return {(path_rates<F>() | ...), (path_rates<F, wrt::speeds>() | ...)};
}
template <class X>
constexpr leaf_set leaves_in() {
  if constexpr (coordinate_info<X>::value)
    return {X::order == 1 ? leaf_bit(X::index) : 0, 0};
  else if constexpr (speed_info<X>::value)
    return {0, X::order == 0 ? leaf_bit(X::index) : 0};
  else if constexpr (std::is_same_v<X, time_variable> || LeafConstant<X> || PoseNumber<X> ||
                     is_unit<X>::value || is_zero_vector_v<X>)
    return {};
  else if constexpr (binary_node(static_cast<X*>(nullptr)))
    return leaves_of<decltype(X::l)> | leaves_of<decltype(X::r)>;
  else if constexpr (is_v<X, scaled>)
    return leaves_of<decltype(X::s)> | leaves_of<decltype(X::v)>;
  else if constexpr (is_v<X, neg> || is_v<X, unary> || power_info<X>::value || is_v<X, call>)
    return leaves_of<decltype(X::x)>;
  else if constexpr (is_v<X, omega>)
    return omega_leaves<typename X::frame>();
  else if constexpr (is_v<X, angular_velocity_of>)
    return omega_leaves<typename X::observer, typename X::body>();
  else if constexpr (is_v<X, vneg> || Quantity<X>)
    return leaves_of<decltype(X::v)>;
  else
    return any_leaf;  // alpha, angular_acceleration_of, unknown nodes: partial_in says why
}
// The set of the leaf Leaf, for the query above.
template <class Leaf>
constexpr leaf_set leaf_query() {
  if constexpr (coordinate_info<Leaf>::value) {
    if constexpr (Leaf::order == 1) return {leaf_bit(Leaf::index), 0};
  } else if constexpr (speed_info<Leaf>::value) {
    if constexpr (Leaf::order == 0) return {0, leaf_bit(Leaf::index)};
  }
  return {0, 0, true};
}

}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
