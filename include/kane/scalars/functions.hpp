// Elementary and opaque functions of scalar expressions: sin, cos, sqrt (one
// node whose tag says how it prints, applies and differentiates), integer
// powers, and user function objects differentiated by dual numbers.
#pragma once

#include <cmath>
#include <type_traits>

#include "kane/detail/dual.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// Elementary functions: sin, cos, sqrt as tags of one node. Each tag says how
// it prints, applies (to numbers or, by ADL, to expressions) and differentiates.
template <ScalarExpr X>
constexpr auto sin(X x);
template <ScalarExpr X>
constexpr auto cos(X x);
template <ScalarExpr X>
constexpr auto sqrt(X x);
// sin, its value and its derivative.
struct sin_fn {
  // the name printed
  static constexpr const char* name = "sin";
  // sin x of a number, or of an expression by ADL
  template <class T>
  static constexpr auto apply(T x) {
    using std::sin;
    return sin(x);
  }
  // cos x: d(sin x)/dx
  template <class X>
  static constexpr auto derivative(X x) {
    return cos(x);
  }
};
// cos, its value and its derivative.
struct cos_fn {
  // the name printed
  static constexpr const char* name = "cos";
  // cos x of a number, or of an expression by ADL
  template <class T>
  static constexpr auto apply(T x) {
    using std::cos;
    return cos(x);
  }
  // -sin x: d(cos x)/dx
  template <class X>
  static constexpr auto derivative(X x) {
    return -sin(x);
  }
};
// sqrt, its value and its derivative.
struct sqrt_fn {
  // the name printed
  static constexpr const char* name = "sqrt";
  // sqrt x of a number, or of an expression by ADL
  template <class T>
  static constexpr auto apply(T x) {
    using std::sqrt;
    return sqrt(x);
  }
  // 1 / (2 sqrt x): d(sqrt x)/dx
  template <class X>
  static constexpr auto derivative(X x);  // 1 / (2 sqrt(x)), below
};
// A named function of a scalar expression (sin, cos, sqrt, ...).
template <class Fn, class X>
struct unary : detail::scalar_tag {
  // the argument
  [[no_unique_address]] X x;
  // Fn(a)
  constexpr explicit unary(X a) : x(a) {}
};
namespace detail {
template <class X>
struct unary_info;
template <class Fn, class A>
struct unary_info<unary<Fn, A>> {
  using fn = Fn;
};
}  // namespace detail

// x^N for an integer N.
template <class X, int N>
struct power : detail::scalar_tag {
  // the base
  [[no_unique_address]] X x;
  // a^N
  constexpr explicit power(X a) : x(a) {}
};
// f(x) for an opaque user function object f, generic in its argument so that
// it runs on dual numbers; derivative_of<F> is f'(x), found by forward mode.
template <class F>
struct derivative_of {
  // the function object
  [[no_unique_address]] F f;
  // f'(x), by one dual number
  template <class T>
  constexpr T operator()(T x) const {
    return f(detail::dual<T>{x, T(1)}).d;
  }
};
// f(x): a user function of a scalar expression, differentiated by dual numbers.
template <class F, class X>
struct call : detail::scalar_tag {
  // the function object
  [[no_unique_address]] F f;
  // the argument
  [[no_unique_address]] X x;
  // g(a)
  constexpr call(F g, X a) : f(g), x(a) {}
};

template <ScalarExpr X>
constexpr auto sin(X x) {
  if constexpr (is_zero_v<X>)
    return zero_t{};
  else
    return unary<sin_fn, X>(x);
}
// cos x; cos 0 = 1
template <ScalarExpr X>
constexpr auto cos(X x) {
  if constexpr (is_zero_v<X>)
    return one_t{};
  else
    return unary<cos_fn, X>(x);
}
// sqrt x
template <ScalarExpr X>
constexpr auto sqrt(X x) {
  return unary<sqrt_fn, X>(x);
}
template <class X>
constexpr auto sqrt_fn::derivative(X x) {
  return constant<1, 2>{} / sqrt(x);
}

// x^N; x^0 = 1, x^1 = x.
template <int N, ScalarExpr X>
constexpr auto pow(X x) {
  if constexpr (N == 0)
    return one_t{};
  else if constexpr (N == 1)
    return x;
  else if constexpr (is_zero_v<X>)
    return zero_t{};
  else
    return power<X, N>(x);
}

// f(x) with f an opaque function object callable on any scalar type.
template <class F, ScalarExpr X>
constexpr auto invoke(F f, X x) {
  return call<F, X>(f, x);
}

}  // namespace kane
#pragma GCC diagnostic pop
