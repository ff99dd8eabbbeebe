// q' and q'' without a speed set: u is q', read from s.qd, or from s.u where s.qd holds 0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

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
  } else {
    const auto m = merge_numbers(d, u);
    out = m.rates;
    return m.conflict;
  }
}
// The bits of u but their signs, ORed in blocks of two: 0 where every number of u is 0 or -0.
template <std::size_t N>
KANE_ALWAYS_INLINE std::uint64_t nonzero_bits(const std::array<double, N>& u) {
  using pair = std::uint64_t __attribute__((vector_size(16)));
  pair b{};
  [&]<std::size_t... K>(std::index_sequence<K...>) KANE_ALWAYS_INLINE_LAMBDA {
    (
        [&]() KANE_ALWAYS_INLINE_LAMBDA {
          pair x;
          std::memcpy(&x, u.data() + 2 * K, sizeof x);
          b |= x;
        }(),
        ...);
  }
  (std::make_index_sequence<N / 2>{});
  std::uint64_t one = 0;
  if constexpr (N % 2) std::memcpy(&one, u.data() + N - 1, sizeof one);
  return (b[0] | b[1] | one) << 1;
}
// q' and, with Qdd, q'' of a state s without a speed set into out (merged_rates); true where one
// conflicts that the level reads (V: q', A: q''). For doubles one test of u and u' first: where both
// hold zeros alone, s.qd and s.qdd.
template <bool Qdd, bool V, bool A, class St>
KANE_ALWAYS_INLINE bool merged_state_rates(St& out, const St& s) {
  if constexpr (std::is_same_v<typename St::scalar, double> && St::nu == St::nq) {
    std::uint64_t bits = nonzero_bits(s.u);
    if constexpr (Qdd) bits |= nonzero_bits(s.ud);
    if (bits == 0) {
      out.qd = s.qd;
      if constexpr (Qdd) out.qdd = s.qdd;
      return false;
    }
    const auto m = merge_out_of_line(s.qd, s.u);
    out.qd = m.rates;
    bool conflict = V && m.conflict;
    if constexpr (Qdd) {
      const auto mm = merge_out_of_line(s.qdd, s.ud);
      out.qdd = mm.rates, conflict = conflict || (A && mm.conflict);
    }
    return conflict;
  } else {
    bool conflict = merged_rates(out.qd, s.qd, s.u) && V;
    if constexpr (Qdd) conflict = (merged_rates(out.qdd, s.qdd, s.ud) && A) || conflict;
    return conflict;
  }
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
