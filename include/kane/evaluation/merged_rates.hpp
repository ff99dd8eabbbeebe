// q' and q'' without a speed set: u is q', read from s.qd, or from s.u where s.qd holds 0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "kane/detail/inline.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S, std::size_t N>
struct merged {
  std::array<S, N> rates;
  bool conflict;
};
// d, or u where d is 0 (-0 keeps its sign); conflict where both hold different nonzero numbers.
template <class S, std::size_t N>
KANE_ALWAYS_INLINE merged<S, N> merge_numbers(const std::array<S, N>& d, const std::array<S, N>& u) {
  merged<S, N> out{{}, false};
  for (std::size_t i = 0; i < N; ++i) {
    const bool given = !(d[i] == S(0)), other = !(u[i] == S(0));
    out.rates[i] = given || !other ? d[i] : u[i];
    out.conflict = out.conflict | (given & other & !(u[i] == d[i]));
  }
  return out;
}
// The same out of line, for a u that holds a nonzero number: by value, so that no address of the
// caller's evaluator escapes.
template <class S, std::size_t N>
[[gnu::noinline]] merged<S, N> merge_out_of_line(std::array<S, N> d, std::array<S, N> u) {
  return merge_numbers(d, u);
}

// Without a speed set u is q' (NU = NQ): out = d, or u where d is 0; true where both hold
// different nonzero numbers.
template <class S, std::size_t NQ, std::size_t NU>
KANE_ALWAYS_INLINE bool merged_rates(std::array<S, NQ>& out, const std::array<S, NQ>& d,
                                     const std::array<S, NU>& u) {
  if constexpr (NU != NQ) {
    out = d;
    return false;
  } else if constexpr (std::is_same_v<S, double>) {
    bool u_zero = true;
    for (std::size_t i = 0; i < NQ; ++i) u_zero = u_zero && u[i] == 0.0;
    if (__builtin_constant_p(u_zero) && u_zero) {  // u known to be 0 (a state just filled): d
      out = d;
      return false;
    }
    std::uint64_t bits = 0;  // u 0 at run time, as where q' is given in s.qd alone: d
    for (std::size_t i = 0; i < NQ; ++i) {
      std::uint64_t b;
      std::memcpy(&b, &u[i], sizeof b);
      bits |= b << 1;  // 0 and -0 alike
    }
    if (bits == 0) {
      out = d;
      return false;
    }
    const auto m = merge_out_of_line(d, u);
    out = m.rates;
    return m.conflict;
  } else {
    const auto m = merge_numbers(d, u);
    out = m.rates;
    return m.conflict;
  }
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
