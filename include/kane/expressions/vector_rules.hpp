// The rules of vector sums, checked on every leaf (vector.hpp applies them).
#pragma once

#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

template <class S, class V>
struct scaled;
template <class L, class R>
struct vsum;
template <class L, class R>
struct vdiff;
template <class V>
struct vneg;

namespace detail {

// The rules of sums, checked on every leaf. A kinematic quantity (^A v^P,
// ^A a^P, ^A w^B, ^A alpha^B, ^A d(.)/dt of one) has an observer, which
// scaling, negation and sums keep; sums of two observers do not compile. A
// cross product (^N w^A x r in the one-point theorem) has none. Every frame of
// an expression belongs to one tree.
template <class V>
struct observer_of {
  using type = void;
};
template <class V>
requires requires { typename V::observer; }
struct observer_of<V> {
  using type = typename V::observer;
};
template <class S, class V>
struct observer_of<scaled<S, V>> : observer_of<V> {};
template <class V>
struct observer_of<vneg<V>> : observer_of<V> {};
template <template <class, class> class T, class L, class R>
requires(is_v<T<L, R>, vsum> || is_v<T<L, R>, vdiff>) struct observer_of<T<L, R>> {
  using type = std::conditional_t<std::is_void_v<typename observer_of<L>::type>,
                                  typename observer_of<R>::type, typename observer_of<L>::type>;
};
template <class V>
using observer_of_t = typename observer_of<V>::type;

// The root of every frame an expression names: void (none), the root, or two_roots<R1, R2>.
template <class R1, class R2>
struct two_roots {};
template <class T>
inline constexpr bool is_two_roots_v = false;
template <class R1, class R2>
inline constexpr bool is_two_roots_v<two_roots<R1, R2>> = true;
template <class A, class B>
constexpr auto join_trees() {
  if constexpr (std::is_void_v<A> || is_two_roots_v<B> || std::is_same_v<A, B>)
    return static_cast<B*>(nullptr);
  else if constexpr (std::is_void_v<B> || is_two_roots_v<A>)
    return static_cast<A*>(nullptr);
  else
    return static_cast<two_roots<A, B>*>(nullptr);
}
template <class A, class B>
using join_trees_t = std::remove_pointer_t<decltype(join_trees<A, B>())>;
template <class X>
struct tree_of;
template <class X>
using tree_of_t = typename tree_of<X>::type;
// The trees of a node's children l and r, s, v, x (void where it has none).
template <class M>
using child_tree_t = tree_of_t<std::remove_cvref_t<M>>;
template <class X>
struct lr_tree {
  using type = void;
};
template <class X>
requires requires { &X::l; }
struct lr_tree<X> {
  using type = join_trees_t<child_tree_t<decltype(X::l)>, child_tree_t<decltype(X::r)>>;
};
template <class X>
struct s_tree {
  using type = void;
};
template <class X>
requires requires { &X::s; }
struct s_tree<X> {
  using type = child_tree_t<decltype(X::s)>;
};
template <class X>
struct v_tree {
  using type = void;
};
template <class X>
requires requires { &X::v; }
struct v_tree<X> {
  using type = child_tree_t<decltype(X::v)>;
};
template <class X>
struct x_tree {
  using type = void;
};
template <class X>
requires requires { &X::x; }
struct x_tree<X> {
  using type = child_tree_t<decltype(X::x)>;
};
template <class X>
using members_tree_t = join_trees_t<join_trees_t<typename lr_tree<X>::type, typename s_tree<X>::type>,
                                    join_trees_t<typename v_tree<X>::type, typename x_tree<X>::type>>;
template <class X>
struct tree_of {
  using type = members_tree_t<X>;
};
template <class X>
requires requires { typename X::frame; }
struct tree_of<X> {
  using type = root_of<typename X::frame>;
};
template <class X>
requires requires { typename X::observer; }
struct tree_of<X> {
  using type = join_trees_t<root_of<typename X::observer>, members_tree_t<X>>;
};

// One tree for the frames of X, Y, ...; the first error names both roots.
template <class T>
inline constexpr bool one_tree_v = true;
template <class R1, class R2>
inline constexpr bool one_tree_v<two_roots<R1, R2>> =
    refused<error::frames_of_two_trees_relate_them_through_a_common_root_frame<R1, R2>>;
template <class L, class R>
inline constexpr bool same_observer_v =
    check<std::is_void_v<observer_of_t<L>> || std::is_void_v<observer_of_t<R>> ||
              std::is_same_v<observer_of_t<L>, observer_of_t<R>>,
          error::quantities_measured_in_different_frames_measure_both_in_one_frame<observer_of_t<L>,
                                                                                   observer_of_t<R>>>;
// L + R, L - R: one tree, one observer (a function: a broken rule adds no error of its own).
template <class L, class R>
constexpr bool summable() {
  return one_tree_v<tree_of_t<vsum<L, R>>> && same_observer_v<L, R>;
}
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
