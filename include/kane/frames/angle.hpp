// Angles of simple rotations: a coordinate q_i, a parameter, a constant, or
// kane::angle<X> for X an expression of coordinates, parameters, numbers and
// the time t, with elementary functions (q<4> + literal(pi / 2), 2 * q<1> - q<2>,
// a named parameter; Omega * t + b * sin(c * t) for a frame driven in time).
//
//   struct H : kane::frame<B, kane::simple<kane::axis::y, kane::angle<kane::q<4> + kane::literal(0.3)>>> {};
//   struct lambda : kane::parameter<5> {};
//   struct T : kane::frame<B, kane::simple<kane::axis::y, lambda>> {};   // head-tube angle
//
// An angle depends on no speed: ^P w^C = theta' k with theta' the total
// derivative of theta (zero for a constant angle, dtheta/dt for a prescribed one).
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// A rotation angle given by a scalar expression X of coordinates, parameters, numbers and t.
template <auto X>
struct angle {
  // X, the angle as a scalar expression
  static constexpr auto value = X;
};

namespace detail {

struct not_an_angle {};

// X with its literals moved into types (fixed<>), or not_an_angle.
template <auto X>
constexpr auto angle_form() {
  using T = std::remove_cv_t<decltype(X)>;
  if constexpr (std::is_same_v<T, literal>)
    return fixed<X>{};
  else if constexpr (is_coordinate<T>::value || Parameter<T> || is_constant<T>::value || is_fixed<T>::value ||
                     std::is_same_v<T, time_variable>)
    return X;
  else if constexpr (is_v<T, unary>) {
    constexpr auto x = angle_form<X.x>();
    if constexpr (std::is_same_v<decltype(x), const not_an_angle>)
      return not_an_angle{};
    else
      return unary<typename unary_info<T>::fn, std::remove_cv_t<decltype(x)>>(x);
  } else if constexpr (is_v<T, neg>) {
    constexpr auto x = angle_form<X.x>();
    if constexpr (std::is_same_v<decltype(x), const not_an_angle>)
      return not_an_angle{};
    else
      return neg(x);
  } else if constexpr (is_v<T, add> || is_v<T, sub> || is_v<T, mul> || is_v<T, quot>) {
    constexpr auto l = angle_form<X.l>();
    constexpr auto r = angle_form<X.r>();
    if constexpr (std::is_same_v<decltype(l), const not_an_angle> ||
                  std::is_same_v<decltype(r), const not_an_angle>)
      return not_an_angle{};
    else
      return [&]<template <class, class> class N, class L, class R>(N<L, R>*) {
        return N(l, r);
      }(static_cast<T*>(nullptr));
  } else
    return not_an_angle{};
}

template <class A>
struct angle_argument {
  static constexpr auto value = not_an_angle{};
};
template <class A>
requires(is_coordinate<A>::value || Parameter<A> || is_constant<A>::value ||
         is_fixed<A>::value) struct angle_argument<A> {
  static constexpr A value{};
};
template <auto X>
struct angle_argument<angle<X>> {
  static constexpr auto value = angle_form<X>();
};

// i when the angle is q_i itself, else 0.
template <class X>
inline constexpr std::size_t bare_coordinate = 0;
template <std::size_t I>
inline constexpr std::size_t bare_coordinate<coordinate<I, 0>> = I;

// theta at the state st (q, p and t).
template <class S, class X, class St>
constexpr S angle_value(const X& x, const St& st) {
  if constexpr (is_coordinate<X>::value) {
    static_assert(X::index <= St::nq,
                  "kane: a rotation angle uses a coordinate beyond the state; "
                  "declare the state with at least that many coordinates");
    return st.q[X::index - 1];
  } else if constexpr (Parameter<X>) {
    static_assert(X::index <= St::np,
                  "kane: a rotation angle uses a parameter beyond the state; "
                  "declare the state with at least that many parameters");
    return st.p[X::index - 1];
  } else if constexpr (is_constant<X>::value)
    return S(X::num) / S(X::den);
  else if constexpr (is_fixed<X>::value)
    return S(X::value);
  else if constexpr (std::is_same_v<X, time_variable>)
    return S(st.t);
  else if constexpr (is_v<X, unary>)
    return unary_info<X>::fn::apply(angle_value<S>(x.x, st));
  else if constexpr (is_v<X, neg>)
    return -angle_value<S>(x.x, st);
  else if constexpr (is_v<X, add>)
    return angle_value<S>(x.l, st) + angle_value<S>(x.r, st);
  else if constexpr (is_v<X, sub>)
    return angle_value<S>(x.l, st) - angle_value<S>(x.r, st);
  else if constexpr (is_v<X, mul>)
    return angle_value<S>(x.l, st) * angle_value<S>(x.r, st);
  else
    return angle_value<S>(x.l, st) / angle_value<S>(x.r, st);
}

}  // namespace detail

template <class A>
concept Angle =
    !std::is_same_v<std::remove_cv_t<decltype(detail::angle_argument<A>::value)>, detail::not_an_angle>;

}  // namespace kane
#pragma GCC diagnostic pop
