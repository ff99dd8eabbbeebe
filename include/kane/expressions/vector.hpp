// Geometric vectors: sums of scalar x unit vector of some frame, cross and dot
// products (seed eq. 2). A vector is one object whatever frames its terms use;
// it becomes numbers only through express<A>(v, evaluator).
//
// Storage rule as for scalars (expr.hpp): operands by value, leaves empty.
#pragma once

#include <concepts>
#include <type_traits>
#include <utility>

#include "kane/expressions/direction_cosines.hpp"
#include "kane/expressions/expr.hpp"
#include "kane/frames/frame.hpp"

namespace kane {

namespace detail {
struct vector_tag {};
}  // namespace detail

template <class T>
concept VectorExpr = std::derived_from<T, detail::vector_tag>;

namespace detail {
struct quantity_tag : vector_tag {};
}  // namespace detail

// A named kinematic quantity (^A v^P, ^A a^P): a node that stands for its expression, member v.
template <class T>
concept Quantity = std::derived_from<T, detail::quantity_tag>;

// e_Fi, i = 1, 2, 3.
template <class F, int I>
struct unit : detail::vector_tag {
  static_assert(I >= 1 && I <= 3, "kane: unit vectors are e<F, 1>, e<F, 2>, e<F, 3>");
  using frame = F;
  static constexpr int index = I;
};
template <Frame F, int I>
inline constexpr unit<F, I> e{};

// The zero vector, as a type.
struct zero_vector : detail::vector_tag {};

template <class S, class V>
struct scaled : detail::vector_tag {
  [[no_unique_address]] S s;
  [[no_unique_address]] V v;
  constexpr scaled(S a, V b) : s(a), v(b) {}
};
template <class L, class R>
struct vsum : detail::vector_tag {
  [[no_unique_address]] L l;
  [[no_unique_address]] R r;
  constexpr vsum(L a, R b) : l(a), r(b) {}
};
template <class L, class R>
struct vdiff : detail::vector_tag {
  [[no_unique_address]] L l;
  [[no_unique_address]] R r;
  constexpr vdiff(L a, R b) : l(a), r(b) {}
};
template <class V>
struct vneg : detail::vector_tag {
  [[no_unique_address]] V v;
  constexpr explicit vneg(V a) : v(a) {}
};
template <class L, class R>
struct vcross : detail::vector_tag {
  [[no_unique_address]] L l;
  [[no_unique_address]] R r;
  constexpr vcross(L a, R b) : l(a), r(b) {}
};
// p . r, a scalar.
template <class L, class R>
struct vdot : detail::scalar_tag {
  [[no_unique_address]] L l;
  [[no_unique_address]] R r;
  constexpr vdot(L a, R b) : l(a), r(b) {}
};

// ^R w^F and ^R alpha^F with R the root of F: atomic, numbers from the
// evaluator's outward pass.
template <class F>
struct omega : detail::vector_tag {
  using frame = F;
};
template <class F>
struct alpha : detail::vector_tag {
  using frame = F;
};

template <class T>
inline constexpr bool is_zero_vector_v = std::is_same_v<T, zero_vector>;

namespace detail {
template <class T>
struct is_vneg : std::false_type {};
template <class V>
struct is_vneg<vneg<V>> : std::true_type {};
template <class T>
struct is_unit : std::false_type {};
template <class F, int I>
struct is_unit<unit<F, I>> : std::true_type {};
// a x b with a an empty (atomic) type; two of them with the same a.
template <class V>
struct cross_with_empty_left : std::false_type {};
template <class A, class B>
struct cross_with_empty_left<vcross<A, B>> : std::bool_constant<std::is_empty_v<A>> {};
template <class L, class R>
struct crosses_with_one_left : std::false_type {};
template <class A, class B, class C>
struct crosses_with_one_left<vcross<A, B>, vcross<A, C>> : std::bool_constant<std::is_empty_v<A>> {};
// Two unit vectors of one frame.
template <class L, class R>
struct same_frame_units : std::false_type {};
template <class F, int I, int J>
struct same_frame_units<unit<F, I>, unit<F, J>> : std::true_type {};
// s v and t v with one (empty) v; v and -v.
template <class L, class R>
struct like_terms : std::false_type {};
template <class S, class T, class V>
struct like_terms<scaled<S, V>, scaled<T, V>> : std::is_empty<V> {};
template <class L, class R>
struct opposite : std::false_type {};
template <class V>
struct opposite<V, vneg<V>> : std::is_empty<V> {};
template <class V>
struct opposite<vneg<V>, V> : std::is_empty<V> {};
template <class L, class R>
constexpr auto unit_cross();
template <class L, class R>
struct unit_cross_reduces : std::false_type {};
template <class A, int I, class B, int J>
struct unit_cross_reduces<unit<A, I>, unit<B, J>>
    : std::bool_constant<!std::is_same_v<decltype(unit_cross<unit<A, I>, unit<B, J>>()), undecided>> {};
// e_Ai x (s e_Bj) or (s e_Ai) x e_Bj when e_Ai x e_Bj reduces.
template <class L, class R>
struct reducible_scaled_cross : std::false_type {};
template <class A, int I, class S, class B, int J>
struct reducible_scaled_cross<unit<A, I>, scaled<S, unit<B, J>>>
    : unit_cross_reduces<unit<A, I>, unit<B, J>> {};
template <class S, class A, int I, class B, int J>
struct reducible_scaled_cross<scaled<S, unit<A, I>>, unit<B, J>>
    : unit_cross_reduces<unit<A, I>, unit<B, J>> {};
}  // namespace detail

template <VectorExpr V>
constexpr auto operator-(V v) {
  if constexpr (is_zero_vector_v<V>)
    return v;
  else if constexpr (detail::is_vneg<V>::value)
    return v.v;
  else
    return vneg<V>(v);
}

// The general sum and difference; kinematic quantities add their own checks
// (angular_velocity.hpp, point.hpp) through more specialised overloads.
template <VectorExpr L, VectorExpr R>
constexpr auto operator+(L l, R r) {
  if constexpr (is_zero_vector_v<L>)
    return r;
  else if constexpr (is_zero_vector_v<R>)
    return l;
  else if constexpr (detail::crosses_with_one_left<L, R>::value)
    return cross(l.l, l.r + r.r);  // a x b + a x c = a x (b + c)
  else if constexpr (detail::like_terms<L, R>::value)
    return (l.s + r.s) * l.v;  // s v + t v = (s + t) v
  else if constexpr (detail::opposite<L, R>::value)
    return zero_vector{};  // v + (-v)
  else
    return vsum<L, R>(l, r);
}
template <VectorExpr L, VectorExpr R>
constexpr auto operator-(L l, R r) {
  if constexpr (is_zero_vector_v<R>)
    return l;
  else if constexpr (is_zero_vector_v<L>)
    return -r;
  else if constexpr (std::is_same_v<L, R> && std::is_empty_v<L>)
    return zero_vector{};  // v - v
  else if constexpr (detail::like_terms<L, R>::value)
    return (l.s - r.s) * l.v;
  else
    return vdiff<L, R>(l, r);
}

template <ScalarOperand S, VectorExpr V>
constexpr auto operator*(S s_, V v) {
  auto s = detail::as_expr(s_);
  using X = decltype(s);
  if constexpr (is_zero_v<X> || is_zero_vector_v<V>)
    return zero_vector{};
  else if constexpr (is_one_v<X>)
    return v;
  else if constexpr (std::is_same_v<X, constant<-1>>)
    return -v;
  else if constexpr (detail::cross_with_empty_left<V>::value)
    return cross(v.l, s * v.r);  // s (a x b) = a x (s b), so that a x b + a x c can merge
  else
    return scaled<X, V>(s, v);
}
template <VectorExpr V, ScalarOperand S>
constexpr auto operator*(V v, S s) {
  return s * v;
}
template <VectorExpr V, ScalarOperand S>
constexpr auto operator/(V v, S s) {
  return (one_t{} / s) * v;
}

namespace detail {
// e_Fi x e_Fj
template <class F, int I, int J>
constexpr auto same_frame_cross() {
  if constexpr (I == J)
    return zero_vector{};
  else if constexpr (J == I % 3 + 1)
    return unit<F, J % 3 + 1>{};
  else
    return -unit<F, I % 3 + 1>{};
}
// e_PI x e_CJ, C turned from its tree parent P about a principal axis: e_CJ = sum_k (e_Pk . e_CJ) e_Pk.
template <class C, int I, int J>
constexpr auto across_edge_cross() {
  using P = typename C::tree_parent;
  return across_edge<C, 1, J>() * same_frame_cross<P, I, 1>() +
         across_edge<C, 2, J>() * same_frame_cross<P, I, 2>() +
         across_edge<C, 3, J>() * same_frame_cross<P, I, 3>();
}
// e_Ai x e_Bj when the tree decides it (expressions/direction_cosines.hpp), undecided otherwise.
template <class L, class R>
constexpr auto unit_cross() {
  using A = typename L::frame;
  using B = typename R::frame;
  constexpr int i = L::index, j = R::index;
  using LA = lifted_t<A, i>;
  using LB = lifted_t<B, j>;
  if constexpr (std::is_same_v<A, B>)
    return same_frame_cross<A, i, j>();
  else if constexpr (std::is_same_v<LA, LB>)
    return same_frame_cross<LA, i, j>();
  else if constexpr (reaches_down<LA, i, B>())  // e_Ai is a unit vector of B
    return same_frame_cross<B, i, j>();
  else if constexpr (reaches_down<LB, j, A>())
    return same_frame_cross<A, i, j>();
  else if constexpr (above_edge<LA, i, LB>())
    return across_edge_cross<LB, i, j>();
  else if constexpr (above_edge<LB, j, LA>())
    return -across_edge_cross<LA, j, i>();
  else
    return undecided{};
}
}  // namespace detail

// p x r as written; e_Fi x e_Fj reduces at compile time.
template <VectorExpr L, VectorExpr R>
constexpr auto cross(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_vector{};
  else if constexpr (detail::same_frame_units<L, R>::value)
    return detail::same_frame_cross<typename L::frame, L::index, R::index>();
  else
    return vcross<L, R>(l, r);
}

namespace detail {
// p x r in what kane derives (derivatives, partial velocities): e_Ai x e_Bj
// reduces whenever the tree decides it.
template <VectorExpr L, VectorExpr R>
constexpr auto derived_cross(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_vector{};
  else if constexpr (unit_cross_reduces<L, R>::value)
    return unit_cross<L, R>();
  else if constexpr (reducible_scaled_cross<L, R>::value) {
    if constexpr (is_unit<L>::value)
      return r.s * unit_cross<L, decltype(r.v)>();  // a x (s b) = s (a x b) when a x b reduces
    else
      return l.s * unit_cross<decltype(l.v), R>();
  } else
    return vcross<L, R>(l, r);
}
}  // namespace detail

namespace detail {
template <class L, class R>
constexpr auto unit_dot() {
  if constexpr (is_unit<L>::value && is_unit<R>::value)
    return tree_dot<typename L::frame, L::index, typename R::frame, R::index>();
  else
    return undecided{};
}
}  // namespace detail

namespace detail {
// e_Fi, s e_Fi or -e_Fi: a dot or cross with one of them is spread over the other operand.
template <class V>
struct unit_like : is_unit<V> {};
template <class S, class V>
struct unit_like<scaled<S, V>> : is_unit<V> {};
template <class V>
struct unit_like<vneg<V>> : is_unit<V> {};
template <class V>
struct spreads : std::false_type {};
template <class S, class V>
struct spreads<scaled<S, V>> : std::true_type {};
template <class V>
struct spreads<vneg<V>> : std::true_type {};
template <class L, class R>
struct spreads<vsum<L, R>> : std::true_type {};
template <class L, class R>
struct spreads<vdiff<L, R>> : std::true_type {};
template <class L, class R>
struct cross_then_unit : std::false_type {};  // (a x b) . c with b x c reducing
template <class A, class B, class C>
struct cross_then_unit<vcross<A, B>, C> : std::bool_constant<unit_like<B>::value && unit_like<C>::value> {};
}  // namespace detail

// p . r as written; e_Fi . e_Fj reduces at compile time.
template <VectorExpr L, VectorExpr R>
constexpr auto dot(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_t{};
  else if constexpr (detail::same_frame_units<L, R>::value)
    return std::conditional_t<L::index == R::index, one_t, zero_t>{};
  else
    return vdot<L, R>(l, r);
}

namespace detail {
template <class T>
constexpr bool has_vdot() {
  if constexpr (is_v<T, vdot>)
    return true;
  else {
    bool found = false;
    if constexpr (requires(T t) { t.l; }) found = found || has_vdot<decltype(std::declval<T>().l)>();
    if constexpr (requires(T t) { t.r; }) found = found || has_vdot<decltype(std::declval<T>().r)>();
    if constexpr (requires(T t) { t.x; }) found = found || has_vdot<decltype(std::declval<T>().x)>();
    if constexpr (requires(T t) { t.s; }) found = found || has_vdot<decltype(std::declval<T>().s)>();
    return found;
  }
}

template <class L, class R>
constexpr auto spread_dot(L l, R r);

// p . r in what kane derives: e_Ai . e_Bj reduces when the tree decides it
// (expressions/direction_cosines.hpp), and a dot with a unit vector spreads over sums and
// scalings when that leaves no dot product to compute.
template <VectorExpr L, VectorExpr R>
constexpr auto derived_dot(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_t{};
  else if constexpr (!std::is_same_v<decltype(unit_dot<L, R>()), undecided>)
    return unit_dot<L, R>();
  else if constexpr (!has_vdot<decltype(spread_dot(l, r))>())
    return spread_dot(l, r);
  else
    return vdot<L, R>(l, r);
}

// l . r spread over the sums and scalings of one operand when the other is a
// unit vector, and (a x b) . c = a . (b x c); a plain vdot otherwise.
template <class L, class R>
constexpr auto spread_dot(L l, R r) {
  if constexpr (unit_like<R>::value && spreads<L>::value) {
    if constexpr (is_v<L, scaled>)
      return l.s * derived_dot(l.v, r);
    else if constexpr (is_v<L, vneg>)
      return -derived_dot(l.v, r);
    else if constexpr (is_v<L, vsum>)
      return derived_dot(l.l, r) + derived_dot(l.r, r);
    else
      return derived_dot(l.l, r) - derived_dot(l.r, r);
  } else if constexpr (unit_like<L>::value && spreads<R>::value)
    return spread_dot(r, l);
  else if constexpr (cross_then_unit<L, R>::value)
    return derived_dot(l.l, derived_cross(l.r, r));
  else if constexpr (cross_then_unit<R, L>::value)
    return derived_dot(r.l, derived_cross(r.r, l));
  else
    return vdot<L, R>(l, r);
}
}  // namespace detail

}  // namespace kane
