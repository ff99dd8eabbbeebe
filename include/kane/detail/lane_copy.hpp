// Copies of arrays of lanes number by number. An array of lanes is large (64 bytes a number for
// eight doubles): g++ copies it whole by a call of memmove, whose dispatch costs more than the
// few vector moves the numbers take. Arrays of other scalars are assigned whole.
#pragma once

#include <array>
#include <cstddef>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/detail/list.hpp"

namespace kane::detail {

// to = from
template <class T>
KANE_ALWAYS_INLINE void assign(T& to, const T& from) {
  to = from;
}
template <class S, std::size_t N>
KANE_ALWAYS_INLINE void assign(std::array<S, N>& to, const std::array<S, N>& from) {
  if constexpr (lane_traits<S>::width > 1)
    static_for_inline<N>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { to[i] = from[i]; });
  else
    to = from;
}
// to = 0
template <class S, std::size_t N>
KANE_ALWAYS_INLINE void assign_zero(std::array<S, N>& to) {
  if constexpr (lane_traits<S>::width > 1)
    static_for_inline<N>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { to[i] = S(0); });
  else
    to = {};
}

}  // namespace kane::detail
