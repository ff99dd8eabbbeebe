// What a careful user adds around generated or hand-written code: every input and every output
// tested finite, without early exit (the exponent bits of each, or-ed: no branch, no chain of
// floating-point latencies); if one is not, every output NaN and the status 1, else 0.
// The twin of a function F is [[gnu::flatten]] void F_checked(in, out) { bench::checked(in, out, F); }
// in F's translation unit, so that F's body and the tests compile as one function.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace bench {

// The sign bit set where x is infinite or NaN (its exponent bits all set), for or-ing.
[[gnu::always_inline]] inline std::uint64_t infinite_bit(double x) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000, one = 0x0010000000000000;
  return (std::bit_cast<std::uint64_t>(x) & exponent) + one;
}

template <class In, class Out, class F>
[[gnu::always_inline]] inline void checked(const In& in, Out& out, F&& f) {
  std::uint64_t bad = 0;
  for (const double x : in.x) bad |= infinite_bit(x);
  f(in, out);
  for (const double x : out.xd) bad |= infinite_bit(x);
  const bool finite = (bad >> 63) == 0;
  if (!finite)
    for (double& x : out.xd) x = std::numeric_limits<double>::quiet_NaN();
  out.status = finite ? 0 : 1;
}

}  // namespace bench
