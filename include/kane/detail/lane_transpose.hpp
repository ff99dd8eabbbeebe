// States in and out of lanes in vector registers (to_lanes and from_lanes of scalars/lanes.hpp): a
// block of W states by W numbers transposed in log2 W stages of two-input shuffles, W shuffles a
// stage.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <utility>

#include "kane/detail/inline.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
namespace kane::detail {

// stage B: rows i and i + B (i & B = 0) swap their off-diagonal blocks of B by B
template <std::size_t B, class V, std::size_t W, std::size_t... C>
KANE_ALWAYS_INLINE void transpose_stage(std::array<V, W>& r, std::index_sequence<C...>) {
  for (std::size_t i = 0; i < W; ++i)
    if ((i & B) == 0) {
      const V a = r[i], b = r[i + B];
      r[i] = __builtin_shufflevector(a, b, ((C & B) ? W + C - B : C)...);
      r[i + B] = __builtin_shufflevector(a, b, ((C & B) ? W + C : C + B)...);
    }
}
// r[k] lane l = r[l] lane k, W a power of two
template <class V, std::size_t W, std::size_t... K>
KANE_ALWAYS_INLINE void transpose(std::array<V, W>& r, std::index_sequence<K...>) {
  (transpose_stage<(W >> (K + 1))>(r, std::make_index_sequence<W>{}), ...);
}
template <class V, std::size_t W>
KANE_ALWAYS_INLINE void transpose(std::array<V, W>& r) {
  transpose(r, std::make_index_sequence<std::bit_width(W) - 1>{});
}

// g++ splits an unaligned load or store of 32 bytes in two for AVX2 targets, and the halves then
// pass through the stack: such vectors load as two halves joined in registers, and store as two
// halves taken in registers
template <class V>
inline constexpr bool split_loads =
#if defined(__GNUC__) && !defined(__clang__) && !defined(__AVX512F__)
    sizeof(V) == 32;
#else
    false;
#endif
// out = the lanes I... of a and b side by side (functions here return no vector: -Wpsabi)
template <class V, class Out, std::size_t... I>
KANE_ALWAYS_INLINE void shuffle(const V& a, const V& b, Out& out, std::index_sequence<I...>) {
  out = __builtin_shufflevector(a, b, I...);
}
// v (W numbers S) = the N numbers of p (N <= W), zeros above, loaded in registers: pieces of powers
// of two joined by shuffles (a wide load of narrow stores would wait on them)
template <std::size_t N, class S, class V>
KANE_ALWAYS_INLINE void load_first(const S* p, V& v) {
  constexpr std::size_t W = sizeof(V) / sizeof(S), h = W / 2;
  v = V{};
  if constexpr (N == W && !split_loads<V>)
    std::memcpy(&v, p, sizeof v);
  else if constexpr (N == 1)
    v[0] = p[0];
  else if constexpr (N > 0) {
    typedef S half __attribute__((vector_size(sizeof(S) * h)));
    half lo, hi;
    load_first<(N < h ? N : h)>(p, lo);
    load_first<(N > h ? N - h : 0)>(p + h, hi);
    shuffle(lo, hi, v, std::make_index_sequence<W>{});
  }
}
template <std::size_t Offset, std::size_t... I>
constexpr std::index_sequence<(Offset + I)...> offset_sequence(std::index_sequence<I...>) {
  return {};
}
// the first N numbers of v (W of S) stored at p, in pieces of powers of two
template <std::size_t N, class S, class V>
KANE_ALWAYS_INLINE void store_first(S* p, const V& v) {
  constexpr std::size_t W = sizeof(V) / sizeof(S), h = W / 2;
  if constexpr (N == W && !split_loads<V>)
    std::memcpy(p, &v, sizeof v);
  else if constexpr (N == 1)
    p[0] = v[0];
  else if constexpr (N > 0) {
    typedef S half __attribute__((vector_size(sizeof(S) * h)));
    half lo, hi;
    shuffle(v, v, lo, std::make_index_sequence<h>{});
    store_first<(N < h ? N : h)>(p, lo);
    if constexpr (N > h) {
      shuffle(v, v, hi, offset_sequence<h>(std::make_index_sequence<h>{}));
      store_first<N - h>(p + h, hi);
    }
  }
}

// x[k] lane l = row(l)[k] for k < N and l < W (L: lanes of W numbers in L::vector v), in blocks
// of W numbers, the last one short
template <std::size_t W, class L, std::size_t N, class Row, std::size_t... B>
KANE_ALWAYS_INLINE void rows_to_lanes(std::array<L, N>& x, const Row& row, std::index_sequence<B...>) {
  (
      [&]() KANE_ALWAYS_INLINE_LAMBDA {
        constexpr std::size_t first = B * W, n = N - first < W ? N - first : W;
        std::array<typename L::vector, W> r;
        for (std::size_t l = 0; l < W; ++l) load_first<n>(row(l) + first, r[l]);
        transpose(r);
        for (std::size_t k = 0; k < n; ++k) x[first + k].v = r[k];
      }(),
      ...);
}
// row(l)[k] = x[k] lane l for k < N and l < count
template <std::size_t W, class L, std::size_t N, class Row, std::size_t... B>
KANE_ALWAYS_INLINE void lanes_to_rows(const std::array<L, N>& x, const Row& row, std::size_t count,
                                      std::index_sequence<B...>) {
  using V = typename L::vector;
  (
      [&]() KANE_ALWAYS_INLINE_LAMBDA {
        constexpr std::size_t first = B * W, n = N - first < W ? N - first : W;
        std::array<V, W> r;
        for (std::size_t k = 0; k < W; ++k) r[k] = k < n ? x[first + k].v : V{};
        transpose(r);
        for (std::size_t l = 0; l < W && l < count; ++l) store_first<n>(row(l) + first, r[l]);
      }(),
      ...);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
