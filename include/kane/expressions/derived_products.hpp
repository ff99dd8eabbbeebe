// Products in what kane derives (derivatives, partial velocities, the
// kinematic equations, constraint coefficients): e_Ai x e_Bj and e_Ai . e_Bj
// reduce whenever the tree decides them (direction_cosines.hpp), and a dot
// with a unit vector spreads over sums and scalings when no dot is left.
// What the user writes keeps its form (cross and dot in vector.hpp).
#pragma once

#include <type_traits>
#include <utility>

#include "kane/expressions/direction_cosines.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

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
template <class L, class R>
constexpr auto unit_dot() {
  if constexpr (is_unit<L>::value && is_unit<R>::value)
    return tree_dot<typename L::frame, L::index, typename R::frame, R::index>();
  else
    return undecided{};
}
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

}  // namespace kane::detail
#pragma GCC diagnostic pop
