// Generalized coordinates q_1..q_n as types (1-based, as in the seed).
#pragma once

#include <cstddef>
#include <type_traits>

namespace kane {

// q_I: the I-th generalized coordinate, stored at index I-1 of a state.
template <std::size_t I>
struct coordinate {
  static_assert(I >= 1, "kane: generalized coordinates are numbered from 1 (q1, q2, ...)");
  static constexpr std::size_t index = I;
};

// q<I> is the tag object of coordinate<I>, e.g. s[q<1>] = 0.3.
template <std::size_t I>
inline constexpr coordinate<I> q{};

namespace detail {
template <class T>
struct is_coordinate : std::false_type {};
template <std::size_t I>
struct is_coordinate<coordinate<I>> : std::true_type {};
}  // namespace detail

template <class T>
concept Coordinate = detail::is_coordinate<T>::value;

}  // namespace kane
