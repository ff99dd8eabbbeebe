// What an expression's literals and constants fix at compile time: a scalar's value, and the
// components of a vector of unit vectors of one frame (their values, and which are 0 or 1).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/patterned.hpp"
#include "kane/detail/structure.hpp"
#include "kane/detail/v3.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// A scalar known at compile time (literals, constants and their arithmetic), and its value.
template <class X>
constexpr bool known_scalar() {
  if constexpr (std::is_same_v<X, literal> || is_constant<X>::value || is_fixed<X>::value)
    return true;
  else if constexpr (is_v<X, add> || is_v<X, sub> || is_v<X, mul> || is_v<X, quot>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().l)>>() &&
           known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().r)>>();
  else if constexpr (is_v<X, neg>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().x)>>();
  else
    return false;
}
template <class X>
constexpr double known_value(const X& x) {
  if constexpr (std::is_same_v<X, literal>)
    return x.value;
  else if constexpr (is_constant<X>::value)
    return double(X::num) / double(X::den);
  else if constexpr (is_fixed<X>::value)
    return X::value;
  else if constexpr (is_v<X, add>)
    return known_value(x.l) + known_value(x.r);
  else if constexpr (is_v<X, sub>)
    return known_value(x.l) - known_value(x.r);
  else if constexpr (is_v<X, mul>)
    return known_value(x.l) * known_value(x.r);
  else if constexpr (is_v<X, quot>)
    return known_value(x.l) / known_value(x.r);
  else
    return -known_value(x.x);
}
// The same for the components of a sum of constants times unit vectors of one frame, in that frame.
template <class V>
constexpr bool known_vector() {
  if constexpr (is_zero_vector_v<V> || is_unit<V>::value)
    return true;
  else if constexpr (is_v<V, scaled>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const V&>().s)>>() &&
           known_vector<std::remove_cv_t<decltype(std::declval<const V&>().v)>>();
  else if constexpr (is_v<V, vneg>)
    return known_vector<std::remove_cv_t<decltype(std::declval<const V&>().v)>>();
  else
    return known_vector<std::remove_cv_t<decltype(std::declval<const V&>().l)>>() &&
           known_vector<std::remove_cv_t<decltype(std::declval<const V&>().r)>>();
}
template <class V>
constexpr std::array<double, 3> known_components(const V& v) {
  if constexpr (is_zero_vector_v<V>)
    return {0, 0, 0};
  else if constexpr (is_unit<V>::value)
    return {double(V::index == 1), double(V::index == 2), double(V::index == 3)};
  else if constexpr (is_v<V, scaled>) {
    const double k = known_value(v.s);
    const auto a = known_components(v.v);
    return {k * a[0], k * a[1], k * a[2]};
  } else if constexpr (is_v<V, vneg>) {
    const auto a = known_components(v.v);
    return {-a[0], -a[1], -a[2]};
  } else {
    const auto a = known_components(v.l), b = known_components(v.r);
    const double sign = is_v<V, vdiff> ? -1.0 : 1.0;
    return {a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2]};
  }
}

// Which of those components are 0 or 1 at every state.
template <class V>
constexpr std::array<entry, 3> own_pattern() {
  if constexpr (is_zero_vector_v<V>)
    return {entry::zero, entry::zero, entry::zero};
  else if constexpr (is_unit<V>::value)
    return {V::index == 1 ? entry::one : entry::zero, V::index == 2 ? entry::one : entry::zero,
            V::index == 3 ? entry::one : entry::zero};
  else if constexpr (is_v<V, scaled> || is_v<V, vneg>)
    return scaled_pattern(own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().v)>>());
  else
    return common_zeros(own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().l)>>(),
                        own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().r)>>());
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
