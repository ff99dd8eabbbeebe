// Scalar expressions in q, q', q'', u, u', t and parameters.
//
// Nodes describe, evaluators compute. Storage rule: every node holds its
// operands by value. Leaves are empty types and the only numbers a node may
// hold are literals (in template arguments they become types, fixed<>), so a
// copy costs nothing and an expression kept in an `auto` variable never refers
// to a temporary. Runtime values live in the state, never in nodes.
//
// Type-level zero and one (constant<0>, constant<1>) vanish from sums and
// products when the expression is built, so derivatives carry no dead terms.
#pragma once

#include <concepts>
#include <cstdint>
#include <numeric>
#include <type_traits>

#include "kane/scalars/coordinate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// the builtin (GCC, Clang): std::derived_from would instantiate std::is_convertible
// for every node type, names of whole expression trees
template <class T>
concept ScalarExpr = __is_base_of(detail::scalar_tag, T);

template <class T>
concept Number = std::is_arithmetic_v<T>;

// N/D, reduced, as a type.
template <std::intmax_t N, std::intmax_t D = 1>
struct constant : detail::scalar_tag {
  static_assert(D != 0, "kane: a constant's denominator must not be zero");
  // N, the numerator
  static constexpr std::intmax_t num = N;
  // D, the denominator
  static constexpr std::intmax_t den = D;
};
// 0 as a constant
using zero_t = constant<0>;
// 1 as a constant
using one_t = constant<1>;

// A number known only at run time (2.5 * q<1>); held by value.
struct literal : detail::scalar_tag {
  // the number
  double value;
  // the number v
  constexpr explicit literal(double v) : value(v) {}
};
// A literal moved into the type: numbers of template arguments (point
// positions, speed definitions, constraints) become constants of the code.
template <literal V>
struct fixed : detail::scalar_tag {
  // V.value, a constant of the code
  static constexpr double value = V.value;
};

// l + r of scalar expressions.
template <class L, class R>
struct add : detail::scalar_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a + b
  constexpr add(L a, R b) : l(a), r(b) {}
};
// l - r of scalar expressions.
template <class L, class R>
struct sub : detail::scalar_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a - b
  constexpr sub(L a, R b) : l(a), r(b) {}
};
// l r of scalar expressions.
template <class L, class R>
struct mul : detail::scalar_tag {
  // the left operand
  [[no_unique_address]] L l;
  // the right operand
  [[no_unique_address]] R r;
  // a b
  constexpr mul(L a, R b) : l(a), r(b) {}
};
// l / r of scalar expressions.
template <class L, class R>
struct quot : detail::scalar_tag {
  // the numerator
  [[no_unique_address]] L l;
  // the denominator
  [[no_unique_address]] R r;
  // a / b
  constexpr quot(L a, R b) : l(a), r(b) {}
};
// -x of a scalar expression.
template <class X>
struct neg : detail::scalar_tag {
  // the operand
  [[no_unique_address]] X x;
  // -a
  constexpr explicit neg(X a) : x(a) {}
};

namespace detail {

// X is an instance of the node template T
template <class X, template <class...> class T>
inline constexpr bool is_v = false;
template <template <class...> class T, class... A>
inline constexpr bool is_v<T<A...>, T> = true;

template <class T>
struct is_fixed : std::false_type {};
template <literal V>
struct is_fixed<fixed<V>> : std::true_type {};
template <class T>
struct is_neg : std::false_type {};
template <class X>
struct is_neg<neg<X>> : std::true_type {};
template <class T>
struct is_constant : std::false_type {};
template <std::intmax_t N, std::intmax_t D>
struct is_constant<constant<N, D>> : std::true_type {};

template <std::intmax_t N, std::intmax_t D>
constexpr auto make_constant() {
  constexpr std::intmax_t g = std::gcd(N, D) * (D < 0 ? -1 : 1);
  return constant<N / g, D / g>{};
}

// x and -x (x empty: equal types are equal expressions)
template <class A, class B>
struct cancels : std::false_type {};
template <class A>
struct cancels<A, neg<A>> : std::is_empty<A> {};
template <class A>
struct cancels<neg<A>, A> : std::is_empty<A> {};

template <class X>
constexpr auto as_expr(X x) {
  if constexpr (ScalarExpr<X>)
    return x;
  else
    return literal(static_cast<double>(x));
}

}  // namespace detail

// T is the constant 0
template <class T>
inline constexpr bool is_zero_v = std::is_same_v<T, zero_t>;
// T is the constant 1
template <class T>
inline constexpr bool is_one_v = std::is_same_v<T, one_t>;

template <class T>
concept ScalarOperand = ScalarExpr<T> || Number<T>;

// -x: a constant folded, -(-x) is x
template <ScalarExpr X>
constexpr auto operator-(X x) {
  if constexpr (detail::is_constant<X>::value)
    return detail::make_constant<-X::num, X::den>();
  else if constexpr (detail::is_neg<X>::value)
    return x.x;
  else
    return neg<X>(x);
}

// l + r, a number as a literal; constants folded, 0 dropped, x + (-x) is 0
template <ScalarOperand L, ScalarOperand R>
requires(ScalarExpr<L> || ScalarExpr<R>) constexpr auto operator+(L l_, R r_) {
  auto l = detail::as_expr(l_);
  auto r = detail::as_expr(r_);
  using A = decltype(l);
  using B = decltype(r);
  if constexpr (is_zero_v<A>)
    return r;
  else if constexpr (is_zero_v<B>)
    return l;
  else if constexpr (detail::is_constant<A>::value && detail::is_constant<B>::value)
    return detail::make_constant<A::num * B::den + B::num * A::den, A::den * B::den>();
  else if constexpr (detail::cancels<A, B>::value)
    return zero_t{};  // x + (-x)
  else
    return add<A, B>(l, r);
}

// l - r, a number as a literal; constants folded, 0 dropped, x - x is 0
template <ScalarOperand L, ScalarOperand R>
requires(ScalarExpr<L> || ScalarExpr<R>) constexpr auto operator-(L l_, R r_) {
  auto l = detail::as_expr(l_);
  auto r = detail::as_expr(r_);
  using A = decltype(l);
  using B = decltype(r);
  if constexpr (is_zero_v<B>)
    return l;
  else if constexpr (is_zero_v<A>)
    return -r;
  else if constexpr (detail::is_constant<A>::value && detail::is_constant<B>::value)
    return detail::make_constant<A::num * B::den - B::num * A::den, A::den * B::den>();
  else if constexpr (std::is_same_v<A, B> && std::is_empty_v<A>)
    return zero_t{};  // x - x
  else
    return sub<A, B>(l, r);
}

// l r, a number as a literal; constants folded, 0 and 1 and -1 simplified
template <ScalarOperand L, ScalarOperand R>
requires(ScalarExpr<L> || ScalarExpr<R>) constexpr auto operator*(L l_, R r_) {
  auto l = detail::as_expr(l_);
  auto r = detail::as_expr(r_);
  using A = decltype(l);
  using B = decltype(r);
  if constexpr (is_zero_v<A> || is_zero_v<B>)
    return zero_t{};
  else if constexpr (is_one_v<A>)
    return r;
  else if constexpr (is_one_v<B>)
    return l;
  else if constexpr (detail::is_constant<A>::value && detail::is_constant<B>::value)
    return detail::make_constant<A::num * B::num, A::den * B::den>();
  else if constexpr (std::is_same_v<A, constant<-1>>)
    return -r;
  else if constexpr (std::is_same_v<B, constant<-1>>)
    return -l;
  else
    return mul<A, B>(l, r);
}

// l / r, a number as a literal; constants folded, 0 / r is 0, l / 1 is l
template <ScalarOperand L, ScalarOperand R>
requires(ScalarExpr<L> || ScalarExpr<R>) constexpr auto operator/(L l_, R r_) {
  auto l = detail::as_expr(l_);
  auto r = detail::as_expr(r_);
  using A = decltype(l);
  using B = decltype(r);
  static_assert(!is_zero_v<B>, "kane: division by the constant zero");
  if constexpr (is_zero_v<A>)
    return zero_t{};
  else if constexpr (is_one_v<B>)
    return l;
  else if constexpr (detail::is_constant<A>::value && detail::is_constant<B>::value)
    return detail::make_constant<A::num * B::den, A::den * B::num>();
  else
    return quot<A, B>(l, r);
}

}  // namespace kane
#pragma GCC diagnostic pop
