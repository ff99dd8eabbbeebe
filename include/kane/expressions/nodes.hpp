// The kinds of expression nodes, a node rebuilt from new children, and freeze: an expression with
// its literals moved into its type.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kane/expressions/vector.hpp"
#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class X>
struct power_info : std::false_type {};
template <class X, int N>
struct power_info<power<X, N>> : std::true_type {
  static constexpr int n = N;
};
template <template <class, class> class T, class L, class R>
constexpr bool binary_node(T<L, R>*) {
  return is_v<T<L, R>, add> || is_v<T<L, R>, sub> || is_v<T<L, R>, mul> || is_v<T<L, R>, quot> ||
         is_v<T<L, R>, vsum> || is_v<T<L, R>, vdiff> || is_v<T<L, R>, vcross> || is_v<T<L, R>, vdot>;
}
constexpr bool binary_node(void*) { return false; }
template <template <class, class> class T, class L, class R, class A, class B>
constexpr auto rebuild(T<L, R>*, A a, B b) {
  return T<A, B>(a, b);
}
template <class Fn, class X, class A>
constexpr auto rebuild(unary<Fn, X>*, A a) {
  return unary<Fn, A>(a);
}

// A template argument that is a scalar expression or a plain number (2, 0.5).
template <auto X>
concept ScalarArgument = ScalarExpr<std::remove_cv_t<decltype(X)>> || Number<std::remove_cv_t<decltype(X)>>;

// The expression X (a template argument) with every literal moved into its
// type: nodes become empty, so derivatives of X cost nothing to build. A plain
// number that is an integer becomes a constant (0.0 a type-level zero), any other a fixed literal.
template <auto X>
constexpr auto freeze() {
  using T = std::remove_cv_t<decltype(X)>;
  if constexpr (Number<T>) {
    if constexpr (X >= T(-1000000) && X <= T(1000000) && X == T(std::intmax_t(X)))
      return constant<std::intmax_t(X)>{};
    else
      return fixed<literal{double(X)}>{};
  } else if constexpr (std::is_same_v<T, literal>)
    return fixed<X>{};
  else if constexpr (std::is_empty_v<T>)
    return X;
  else if constexpr (binary_node(static_cast<T*>(nullptr)))
    return rebuild(static_cast<T*>(nullptr), freeze<X.l>(), freeze<X.r>());
  else if constexpr (is_v<T, scaled>)
    return scaled(freeze<X.s>(), freeze<X.v>());
  else if constexpr (is_v<T, neg>)
    return neg(freeze<X.x>());
  else if constexpr (is_v<T, vneg>)
    return vneg(freeze<X.v>());
  else if constexpr (is_v<T, unary>)
    return rebuild(static_cast<T*>(nullptr), freeze<X.x>());
  else if constexpr (power_info<T>::value)
    return power<decltype(freeze<X.x>()), power_info<T>::n>(freeze<X.x>());
  else
    return X;  // a call keeps its function object
}

template <class X>
struct coordinate_info : std::false_type {};
template <std::size_t I, std::size_t D>
struct coordinate_info<coordinate<I, D>> : std::true_type {};
template <class X>
struct speed_info : std::false_type {};
template <std::size_t I, std::size_t D>
struct speed_info<speed<I, D>> : std::true_type {};

// A number the evaluator computes from q and t alone (W and X of the kinematic equations): it
// holds no rate or speed, and X::time_derivative() is its time derivative as an expression.
struct pose_number_tag {};
template <class X>
concept PoseNumber = __is_base_of(pose_number_tag, X);

// The number 1 that names a speed set (kane::speed_set_one): a constant that only an evaluator of
// that speed set reads.
struct bound_one_tag {};
template <class X>
concept BoundOne = __is_base_of(bound_one_tag, X);

template <class X>
concept LeafConstant = is_constant<X>::value || std::is_same_v<X, literal> || is_fixed<X>::value ||
    Parameter<X> || Input<X> || BoundOne<X>;

}  // namespace kane::detail
#pragma GCC diagnostic pop
