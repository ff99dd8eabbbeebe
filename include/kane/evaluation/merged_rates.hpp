// q' and q'' without a speed set: u is q', read from s.qd, or from s.u where s.qd holds 0.
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/wide_stores.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// Without a speed set u is q' (NU = NQ): out = d, or u where d is 0; true where both hold
// different nonzero numbers.
template <class S, std::size_t NQ, std::size_t NU>
KANE_ALWAYS_INLINE bool merged_rates(std::array<S, NQ>& out, const std::array<S, NQ>& d,
                                     const std::array<S, NU>& u) {
  if constexpr (NU != NQ) {
    out = d;
    return false;
  } else if constexpr (std::is_same_v<S, double> && NQ >= 2) {  // in blocks: no branch per number
    bool u_zero = true;
    for (std::size_t i = 0; i < NQ; ++i) u_zero = u_zero && u[i] == 0.0;
    if (__builtin_constant_p(u_zero) && u_zero) {  // u known to be 0 (a state just filled): d
      out = d;
      return false;
    }
    using wide = typename block_of<widest_store>::type;
    using pair = typename block_of<2>::type;
    constexpr std::size_t w = widest_store, wide_end = NQ / w * w,
                          pair_end = wide_end + (NQ - wide_end) / 2 * 2;
    decltype(wide{} != wide{}) any_wide{};
    decltype(pair{} != pair{}) any_pair{};
    const auto merge = [&](auto block, std::size_t k, auto& any) KANE_ALWAYS_INLINE_LAMBDA {
      using B = decltype(block);
      B x, y;  // number by number, unrolled: known numbers of d and u stay known
      [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
        ((x[I] = d[k + I], y[I] = u[k + I]), ...);
      }
      (std::make_index_sequence<sizeof x / sizeof x[0]>{});
      const auto given = x != B{}, other = y != B{};
      const B r = (given | ~other) ? x : y;  // d where u is 0 (-0 keeps its sign)
      std::memcpy(out.data() + k, &r, sizeof r);
      any |= given & other & (x != y);
    };
    for (std::size_t k = 0; k < wide_end; k += w) merge(wide{}, k, any_wide);
    if constexpr (pair_end > wide_end) merge(pair{}, wide_end, any_pair);
    bool conflict = false;
    for (std::size_t i = 0; i < w; ++i) conflict = conflict | (any_wide[i] != 0);
    conflict = conflict | (any_pair[0] != 0) | (any_pair[1] != 0);
    if constexpr (NQ > pair_end) {
      const bool given = !(d[NQ - 1] == S(0)), other = !(u[NQ - 1] == S(0));
      out[NQ - 1] = given || !other ? d[NQ - 1] : u[NQ - 1];
      conflict = conflict | (given & other & !(u[NQ - 1] == d[NQ - 1]));
    }
    return conflict;
  } else {
    bool conflict = false;
    for (std::size_t i = 0; i < NQ; ++i) {
      const bool given = !(d[i] == S(0)), other = !(u[i] == S(0));
      out[i] = given || !other ? d[i] : u[i];  // d where u is 0 (-0 keeps its sign)
      conflict = conflict | (given & other & !(u[i] == d[i]));
    }
    return conflict;
  }
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
