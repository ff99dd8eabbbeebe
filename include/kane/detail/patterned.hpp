// Arithmetic with factors known at compile time to be 0 or 1 at every state
// (pattern 0 or 1; any_value otherwise): such factors are not multiplied and
// such terms not added. A compiler cannot drop x * 0.0 or x + 0.0 itself (NaN,
// infinities and -0.0), and on jets it sees no constants at all.
#pragma once

#include <array>
#include <cstddef>

#include "kane/detail/inline.hpp"

namespace kane::detail {

inline constexpr int any_value = 2;
constexpr int pattern_of(double c) { return c == 0.0 ? 0 : c == 1.0 ? 1 : any_value; }

// x y, y of pattern Y
template <int Y, class S>
KANE_ALWAYS_INLINE S times(const S& x, const S& y) {
  if constexpr (Y == 0)
    return S(0);
  else if constexpr (Y == 1)
    return x;
  else
    return x * y;
}
// a x + b y and a x - b y, x and y of patterns X and Y
template <int X, int Y, class S>
KANE_ALWAYS_INLINE S plus(const S& a, const S& x, const S& b, const S& y) {
  if constexpr (Y == 0)
    return times<X>(a, x);
  else if constexpr (X == 0)
    return times<Y>(b, y);
  else
    return times<X>(a, x) + times<Y>(b, y);
}
template <int X, int Y, class S>
KANE_ALWAYS_INLINE S minus(const S& a, const S& x, const S& b, const S& y) {
  if constexpr (Y == 0)
    return times<X>(a, x);
  else if constexpr (X == 0)
    return -times<Y>(b, y);
  else
    return times<X>(a, x) - times<Y>(b, y);
}

// Columns e_1, e_2, e_3 (9 numbers, column after column) turned about their own e_p:
// e_p stays, e_a = c e_a + s e_b and e_b = c e_b - s e_a mix (a, b the other two).
constexpr std::array<int, 9> turned_columns(const std::array<int, 9>& parent, int axis) {
  std::array<int, 9> out{};
  const auto p = std::size_t(axis), a = (p + 1) % 3, b = (p + 2) % 3;
  for (std::size_t i = 0; i < 3; ++i) {
    out[3 * p + i] = parent[3 * p + i];
    out[3 * a + i] = out[3 * b + i] = parent[3 * a + i] == 0 && parent[3 * b + i] == 0 ? 0 : any_value;
  }
  return out;
}

}  // namespace kane::detail
