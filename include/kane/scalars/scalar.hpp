// Scalars: the number types components and matrices are made of.
#pragma once

#include <concepts>

#include "kane/detail/lane_traits.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// Specialise to admit a new number type (dual numbers, interval types).
template <class S>
struct is_scalar : std::bool_constant<std::floating_point<S>> {};

// The real numbers S is built on (S itself; a jet's value type).
template <class S>
struct real_type {
  // S: a floating-point type is its own real type
  using type = S;
};

template <class S>
concept Scalar = is_scalar<S>::value;

// float, double, or kane::lanes of them (kane/scalars/lanes.hpp): numbers, not jets.
template <class S>
concept Numbers = std::floating_point<S> ||(lane_traits<S>::width > 1);

}  // namespace kane
#pragma GCC diagnostic pop
