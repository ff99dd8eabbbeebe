// Geometric vectors: sums of scalar x unit vector of some frame, cross and dot
// products (seed eq. 2). A vector is one object whatever frames its terms use;
// it becomes numbers only through express<A>(v, evaluator).
//
// Storage rule as for scalars (expr.hpp): operands by value, leaves empty.
#pragma once

#include <concepts>
#include <type_traits>

#include "kane/detail/cosines.hpp"
#include "kane/expr.hpp"
#include "kane/frame.hpp"

namespace kane {

namespace detail {
struct vector_tag {};
}  // namespace detail

template <class T>
concept VectorExpr = std::derived_from<T, detail::vector_tag>;

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
// Two unit vectors of one frame once lifted (detail/cosines.hpp).
template <class L, class R>
struct same_lifted_units : std::false_type {};
template <class A, int I, class B, int J>
struct same_lifted_units<unit<A, I>, unit<B, J>>
    : std::bool_constant<std::is_same_v<lifted_t<A, I>, lifted_t<B, J>>> {};
// e_Ai x (s e_Bj) or (s e_Ai) x e_Bj with the units of one lifted frame.
template <class L, class R>
struct reducible_scaled_cross : std::false_type {};
template <class A, int I, class S, class B, int J>
struct reducible_scaled_cross<unit<A, I>, scaled<S, unit<B, J>>> : same_lifted_units<unit<A, I>, unit<B, J>> {
};
template <class S, class A, int I, class B, int J>
struct reducible_scaled_cross<scaled<S, unit<A, I>>, unit<B, J>> : same_lifted_units<unit<A, I>, unit<B, J>> {
};
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
  else
    return vsum<L, R>(l, r);
}
template <VectorExpr L, VectorExpr R>
constexpr auto operator-(L l, R r) {
  if constexpr (is_zero_vector_v<R>)
    return l;
  else if constexpr (is_zero_vector_v<L>)
    return -r;
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

// p x r; e_Fi x e_Fj reduces at compile time.
template <VectorExpr L, VectorExpr R>
constexpr auto cross(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_vector{};
  else if constexpr (detail::same_frame_units<L, R>::value || detail::same_lifted_units<L, R>::value) {
    using F = std::conditional_t<detail::same_frame_units<L, R>::value, typename L::frame,
                                 detail::lifted_t<typename L::frame, L::index>>;
    constexpr int i = L::index, j = R::index;
    if constexpr (i == j)
      return zero_vector{};
    else if constexpr (j == i % 3 + 1)
      return unit<F, j % 3 + 1>{};
    else
      return -unit<F, i % 3 + 1>{};
  } else if constexpr (detail::reducible_scaled_cross<L, R>::value) {
    if constexpr (detail::is_unit<L>::value)
      return r.s * cross(l, r.v);  // a x (s b) = s (a x b) when a x b reduces
    else
      return l.s * cross(l.v, r);
  } else
    return vcross<L, R>(l, r);
}

namespace detail {
template <class L, class R>
constexpr auto unit_dot() {
  if constexpr (is_unit<L>::value && is_unit<R>::value)
    return tree_dot<typename L::frame, L::index, typename R::frame, R::index>();
  else
    return undecided{};
}
}  // namespace detail

// p . r; e_Ai . e_Bj reduces at compile time when the tree decides it (detail/cosines.hpp).
template <VectorExpr L, VectorExpr R>
constexpr auto dot(L l, R r) {
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_t{};
  else if constexpr (!std::is_same_v<decltype(detail::unit_dot<L, R>()), detail::undecided>)
    return detail::unit_dot<L, R>();
  else
    return vdot<L, R>(l, r);
}

}  // namespace kane
