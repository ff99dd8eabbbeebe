// Scalars: the number types components and matrices are made of.
#pragma once

#include <concepts>

namespace kane {

// Specialise to admit a new number type (dual numbers, interval types).
template <class S>
struct is_scalar : std::bool_constant<std::floating_point<S>> {};

template <class S>
concept Scalar = is_scalar<S>::value;

}  // namespace kane
