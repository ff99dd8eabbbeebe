// Numbers stored in 16-byte pairs. A wide load of numbers that were stored one by one waits
// until each store has left the store buffer; a load of a pair stored whole is forwarded.
// Eigen's fixed-size copies and products read doubles in such pairs.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"

namespace kane::detail {

// to[i] = value(std::integral_constant<std::size_t, i>{}) for i < N: doubles by pairs.
template <std::size_t N, class S, class F>
KANE_ALWAYS_INLINE void store_by_pairs(S* to, const F& value) {
  [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
    if constexpr (std::is_same_v<S, double>) {
      using pair = double __attribute__((vector_size(16)));
      (
          [&] {
            const pair p = {double(value(std::integral_constant<std::size_t, 2 * I>{})),
                            double(value(std::integral_constant<std::size_t, 2 * I + 1>{}))};
            std::memcpy(to + 2 * I, &p, sizeof p);
          }(),
          ...);
      if constexpr (N % 2 == 1) to[N - 1] = value(std::integral_constant<std::size_t, N - 1>{});
    } else {
      ((to[2 * I] = value(std::integral_constant<std::size_t, 2 * I>{}),
        to[2 * I + 1] = value(std::integral_constant<std::size_t, 2 * I + 1>{})),
       ...);
      if constexpr (N % 2 == 1) to[N - 1] = value(std::integral_constant<std::size_t, N - 1>{});
    }
  }
  (std::make_index_sequence<N / 2>{});
}

}  // namespace kane::detail
