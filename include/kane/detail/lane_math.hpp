// The functions of kane::lanes (scalars/lanes.hpp) in vector registers, on GCC's and Clang's vector
// types of W numbers of S: sine and cosine by kane's own kernels, square roots by the target's
// instruction.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#if defined(__AVX__)  // the intrinsics of the target's widest set, as Eigen includes them
#include <immintrin.h>
#elif defined(__SSE4_1__)
#include <smmintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "kane/detail/inline.hpp"
#include "kane/detail/packet.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
namespace kane::detail {

// Whether every lane of a mask m is true (all bits set; false: none): one test of the register where
// the target has one, else lane by lane.
template <class M>
KANE_ALWAYS_INLINE bool all_lanes(const M& m) {
#if defined(__AVX512F__)
  if constexpr (sizeof(M) == 64)
    return _mm512_cmpneq_epi32_mask(std::bit_cast<__m512i>(m), _mm512_set1_epi32(-1)) == 0;
#endif
#if defined(__AVX__)
  if constexpr (sizeof(M) == 32)
    return _mm256_testc_si256(std::bit_cast<__m256i>(m), _mm256_set1_epi32(-1)) != 0;
#endif
#if defined(__SSE4_1__)
  if constexpr (sizeof(M) == 16) return _mm_testc_si128(std::bit_cast<__m128i>(m), _mm_set1_epi32(-1)) != 0;
#elif defined(__SSE2__)
  if constexpr (sizeof(M) == 16) return _mm_movemask_epi8(std::bit_cast<__m128i>(m)) == 0xffff;
#endif
  bool all = true;
  for (std::size_t i = 0; i < sizeof(M) / sizeof(m[0]); ++i) all = all && m[i] != 0;
  return all;
}

// sin x and cos x in every lane, in vector registers for |x| <= 1e5 (doubles; floats 8192): x =
// k pi/2 + r, |r| <= pi/4, and polynomials in r (fdlibm's kernels; for floats Cephes'), within an
// ulp or two of std::sin and std::cos. Other lanes (large, inf, NaN) take std::sin and std::cos.
// k's quadrant picks and signs are bit operations: no compare of 64-bit integers, which SSE2 lacks.
template <class S, std::size_t W, class vector>
KANE_ALWAYS_INLINE void lane_sincos(const vector& x, vector& s, vector& c) {
  constexpr bool dbl = std::is_same_v<S, double>;
  using I = std::conditional_t<dbl, long long, int>;
  typedef I ints __attribute__((vector_size(sizeof(S) * W)));
  const ints sign = ints{} + std::numeric_limits<I>::min();  // the sign bit alone
  const ints near = __builtin_bit_cast(vector, __builtin_bit_cast(ints, x) & ~sign) <= S(dbl ? 1e5 : 8192);
  const bool all = all_lanes(near);
  const vector xr = __builtin_bit_cast(vector, near & __builtin_bit_cast(ints, x));
  // k = round(x 2/pi), |k| < 2^17: x 2/pi plus a half of x's sign, truncated; in 32 bits where the
  // target converts doubles to 32-bit integers only, widened once
  const vector t = xr * S(0.63661977236758134308) +
                   __builtin_bit_cast(vector, __builtin_bit_cast(ints, vector{} + S(0.5)) |
                                                  (__builtin_bit_cast(ints, xr) & sign));
#ifdef __AVX512DQ__
  const ints k = __builtin_convertvector(t, ints);
  const vector kd = __builtin_convertvector(k, vector);
#else
  typedef int ints32 __attribute__((vector_size(sizeof(int) * W)));
  const ints32 k32 = __builtin_convertvector(t, ints32);
  const ints k = __builtin_convertvector(k32, ints);
  const vector kd = __builtin_convertvector(k32, vector);
#endif
  vector r, sr, cr;
  if constexpr (dbl) {
    // pi/2 = p1 + p2 + p3 + p4, p1 .. p3 of 33 bits: k p_i is exact for |k| < 2^20 (fdlibm's split)
    r = xr - kd * 1.57079632673412561417e+00 - kd * 6.07710050630396597660e-11 -
        kd * 2.02226624871116645580e-21 - kd * 8.47842766036889956997e-32;
    const vector z = r * r;
    sr = r + r * z *
                 (-1.66666666666666324348e-01 +
                  z * (8.33333333332248946124e-03 +
                       z * (-1.98412698298579493134e-04 +
                            z * (2.75573137070700676789e-06 +
                                 z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
    cr = 1.0 - 0.5 * z +
         z * z *
             (4.16666666666666019037e-02 +
              z * (-1.38888888888741095749e-03 +
                   z * (2.48015872894767294178e-05 +
                        z * (-2.75573143513906633035e-07 +
                             z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
  } else {
    r = xr - kd * 1.5703125f - kd * 4.837512969970703125e-4f - kd * 7.54978995489188216e-8f;
    const vector z = r * r;
    sr = r + r * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    cr = 1.0f - 0.5f * z +
         z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
  }
  // masks of all ones or zeros from k's low bits, and sign bits from bit 1 of k and of k + 1
  constexpr int up = 8 * sizeof(I) - 2;
  const ints odd = -(k & 1), sn = (k << up) & sign, cn = ((k + 1) << up) & sign;
  const ints sb = __builtin_bit_cast(ints, sr) | (__builtin_bit_cast(ints, r) & sign),
             cb = __builtin_bit_cast(ints, cr);  // sin -0 = -0
  s = __builtin_bit_cast(vector, ((odd & cb) | (~odd & sb)) ^ sn);
  c = __builtin_bit_cast(vector, ((odd & sb) | (~odd & cb)) ^ cn);
  if (!all)
    for (std::size_t i = 0; i < W; ++i)
      if (!near[i]) s[i] = std::sin(x[i]), c[i] = std::cos(x[i]);
}

// sqrt in every lane: the target's instruction on each of the widest registers that W fills (lane by
// lane below SSE2 or below 16 bytes)
template <class S, std::size_t W, class vector>
KANE_ALWAYS_INLINE vector lane_sqrt(const vector& a) {
  vector r;
#if defined(__SSE2__)
  if constexpr (sizeof(vector) >= 16) {
    constexpr std::size_t bytes = sizeof(vector) < register_bytes ? sizeof(vector) : register_bytes;
    constexpr bool dbl = std::is_same_v<S, double>;
    typedef S reg __attribute__((vector_size(bytes)));
    for (std::size_t at = 0; at < sizeof(vector); at += bytes) {
      reg x;
      std::memcpy(&x, reinterpret_cast<const char*>(&a) + at, bytes);
#if defined(__AVX512F__)
      if constexpr (bytes == 64 && dbl)
        x = std::bit_cast<reg>(_mm512_sqrt_pd(std::bit_cast<__m512d>(x)));
      else if constexpr (bytes == 64)
        x = std::bit_cast<reg>(_mm512_sqrt_ps(std::bit_cast<__m512>(x)));
      else
#endif
#if defined(__AVX__)
          if constexpr (bytes == 32 && dbl)
        x = std::bit_cast<reg>(_mm256_sqrt_pd(std::bit_cast<__m256d>(x)));
      else if constexpr (bytes == 32)
        x = std::bit_cast<reg>(_mm256_sqrt_ps(std::bit_cast<__m256>(x)));
      else
#endif
          if constexpr (dbl)
        x = std::bit_cast<reg>(_mm_sqrt_pd(std::bit_cast<__m128d>(x)));
      else
        x = std::bit_cast<reg>(_mm_sqrt_ps(std::bit_cast<__m128>(x)));
      std::memcpy(reinterpret_cast<char*>(&r) + at, &x, bytes);
    }
    return r;
  }
#endif
  for (std::size_t i = 0; i < W; ++i) r[i] = std::sqrt(a[i]);
  return r;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
