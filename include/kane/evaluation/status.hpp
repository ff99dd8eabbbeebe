// What a numeric solve found: ok, a singular matrix (a pivot at or below the
// rank threshold), or numbers that are not finite (NaN or inf in or out).
// ok promises finite numbers: the promise rests on IEEE comparisons with NaN,
// which -ffast-math and -ffinite-math-only let the compiler fold away, so
// those flags are an error here unless KANE_ALLOW_FAST_MATH is defined (then
// status() may say ok for NaN or infinite numbers).
#pragma once

#include <array>
#include <cstddef>

#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) && \
    !defined(KANE_ALLOW_FAST_MATH)
#error "kane: finite math only (-ffast-math) voids solve_status: build without or define KANE_ALLOW_FAST_MATH"
#endif

namespace kane {

enum class solve_status { ok, singular, not_finite };

namespace detail {
// Every number of a is finite: x - x is 0 for a finite x, NaN otherwise.
template <class S, std::size_t N>
bool all_finite(const std::array<S, N>& a) {
  bool finite = true;
  for (const S& x : a) finite = finite & (x - x == S(0));
  return finite;
}
}  // namespace detail

}  // namespace kane
