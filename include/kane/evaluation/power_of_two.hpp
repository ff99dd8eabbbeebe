// Powers of two that scale a solve (evaluation/block_solve.hpp): exact, so a scaled matrix and its
// solution carry no rounding from the scale.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/scalars/scalar.hpp"

namespace kane::detail {

// 2^e, exactly, in a constant expression.
template <class S>
constexpr S pow2(int e) {
  S x = S(1);
  for (; e > 0; --e) x *= S(2);
  for (; e < 0; ++e) x /= S(2);
  return x;
}

// 2^-e with 2^(e-1) <= x < 2^e (frexp's e), e clamped to [min_exponent - 2, max_exponent - 2] so
// that 2^-e is normal; x finite and positive. For doubles from the bits: no call, which would keep
// the stores of a local evaluator alive.
template <class S>
KANE_ALWAYS_INLINE auto inverse_power_of_two(const S& x) {
  using real = typename real_type<S>::type;
  using limits = std::numeric_limits<real>;
  if constexpr (lane_traits<S>::width > 1 && std::is_same_v<real, double> && limits::is_iec559) {
    using vector = typename S::vector;  // the doubles' bits, as below, in every lane
    typedef long long ints __attribute__((vector_size(sizeof(vector))));
    const ints biased = (__builtin_bit_cast(ints, x.v) >> 52) & 0x7ff;  // a builtin: no call returns a vector
    ints e = biased != 0 ? biased - 1022 : x.v >= pow2<double>(-1023) ? ints{} - 1022 : ints{} - 1023;
    e = e > limits::max_exponent - 2 ? ints{} + (limits::max_exponent - 2) : e;  // e >= -1023 always
    return S(__builtin_bit_cast(vector, (1023 - e) << 52));
  } else if constexpr (lane_traits<S>::width > 1) {  // lane by lane
    S r;
    for (std::size_t i = 0; i < lane_traits<S>::width; ++i) r.set(i, inverse_power_of_two(x[i]));
    return r;
  } else {
    int e = 0;
    if constexpr (std::is_same_v<S, double> && limits::is_iec559) {
      const int biased = int((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
      e = biased != 0 ? biased - 1022 : x >= pow2<double>(-1023) ? -1022 : -1023;  // subnormal: clamped
    } else {
      using std::frexp;
      frexp(x, &e);
    }
    if (e < limits::min_exponent - 2) e = limits::min_exponent - 2;  // a subnormal scale
    if (e > limits::max_exponent - 2) e = limits::max_exponent - 2;
    if constexpr (std::is_same_v<real, double> && limits::is_iec559)
      return std::bit_cast<double>(std::uint64_t(1023 - e) << 52);
    else {
      using std::ldexp;
      return ldexp(real(1), -e);
    }
  }
}

}  // namespace kane::detail
