// Geometric vectors: sums of scalar x unit vector of some frame, cross and dot
// products. A vector is one object whatever frames its terms use;
// it becomes numbers only through express<A>(v, evaluator).
//
// Storage rule as for scalars (expr.hpp): operands by value, leaves empty.
#pragma once

#include <concepts>
#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/expressions/vector_rules.hpp"
#include "kane/frames/frame.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct vector_tag {};
}  // namespace detail

// the builtin (GCC, Clang): std::derived_from would instantiate std::is_convertible
// for every node type, names of whole expression trees
template <class T>
concept VectorExpr = __is_base_of(detail::vector_tag, T);

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
  // F, the frame of the unit vector
  using frame = F;
  // i of e_Fi
  static constexpr int index = I;
};
// e<F, i> is e_Fi
template <Frame F, int I>
inline constexpr unit<F, I> e{};

// The zero vector, as a type.
struct zero_vector : detail::vector_tag {};

// s v: a scalar expression times a vector expression.
template <class S, class V>
struct scaled : detail::vector_tag {
  // the scalar factor
  [[no_unique_address]] S s;
  // the vector
  [[no_unique_address]] V v;
  // a b
  constexpr scaled(S a, V b) : s(a), v(b) {}
};
// l + r of vector expressions.
template <class L, class R>
struct vsum : detail::vector_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a + b
  constexpr vsum(L a, R b) : l(a), r(b) {}
};
// l - r of vector expressions.
template <class L, class R>
struct vdiff : detail::vector_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a - b
  constexpr vdiff(L a, R b) : l(a), r(b) {}
};
// -v of a vector expression.
template <class V>
struct vneg : detail::vector_tag {
  // the operand
  [[no_unique_address]] V v;
  // -a
  constexpr explicit vneg(V a) : v(a) {}
};
// l x r of vector expressions.
template <class L, class R>
struct vcross : detail::vector_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a x b
  constexpr vcross(L a, R b) : l(a), r(b) {}
};
// p . r, a scalar.
template <class L, class R>
struct vdot : detail::scalar_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a . b
  constexpr vdot(L a, R b) : l(a), r(b) {}
};

// ^R w^F and ^R alpha^F with R the root of F: atomic, numbers from the
// evaluator's outward pass.
template <class F>
struct omega : detail::vector_tag {
  // F, whose angular velocity this is
  using frame = F;
};
// ^R alpha^F, the angular acceleration of F in the root R: a leaf the evaluator computes.
template <class F>
struct alpha : detail::vector_tag {
  // F, whose angular acceleration this is
  using frame = F;
};

// T is the zero vector
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

}  // namespace detail

// -v; -0 is 0, -(-v) is v
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
  static_assert(detail::summable<L, R>());
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
// l - r; 0 dropped, v - v is 0, s v - t v is (s - t) v
template <VectorExpr L, VectorExpr R>
constexpr auto operator-(L l, R r) {
  static_assert(detail::summable<L, R>());
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

// s v, a number as a literal; 0, 1 and -1 simplified, s (a x b) is a x (s b)
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
// v s = s v
template <VectorExpr V, ScalarOperand S>
constexpr auto operator*(V v, S s) {
  return s * v;
}
// v / s = (1/s) v
template <VectorExpr V, ScalarOperand S>
constexpr auto operator/(V v, S s) {
  return (one_t{} / s) * v;
}
// v / |v|: a unit vector along v (NaN where v is zero at a state).
template <VectorExpr V>
constexpr auto normalized(V v) {
  static_assert(!is_zero_vector_v<V>, "kane: normalized(v) of the zero vector has no direction");
  return v / sqrt(dot(v, v));
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
}  // namespace detail

// p x r as written; e_Fi x e_Fj reduces at compile time.
template <VectorExpr L, VectorExpr R>
constexpr auto cross(L l, R r) {
  static_assert(detail::one_tree_v<detail::tree_of_t<vcross<L, R>>>);
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_vector{};
  else if constexpr (detail::same_frame_units<L, R>::value)
    return detail::same_frame_cross<typename L::frame, L::index, R::index>();
  else
    return vcross<L, R>(l, r);
}

// p . r as written; e_Fi . e_Fj reduces at compile time.
template <VectorExpr L, VectorExpr R>
constexpr auto dot(L l, R r) {
  static_assert(detail::one_tree_v<detail::tree_of_t<vcross<L, R>>>);
  if constexpr (is_zero_vector_v<L> || is_zero_vector_v<R>)
    return zero_t{};
  else if constexpr (detail::same_frame_units<L, R>::value)
    return std::conditional_t<L::index == R::index, one_t, zero_t>{};
  else
    return vdot<L, R>(l, r);
}

}  // namespace kane
#pragma GCC diagnostic pop
