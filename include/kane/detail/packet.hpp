// A packet: the numbers of a few columns or rows that one vector register holds, for loops that
// treat them alike (the solves of invert.hpp and articulated_solve.hpp, the columns of
// rnea_derivatives.hpp). g++ and clang++ take their vector extension for float and double; other
// scalars and compilers take Eigen's fixed-size array.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"

namespace kane::detail {

// The bytes of the widest vector register the target enables.
inline constexpr std::size_t register_bytes =
#if defined(__AVX512F__)
    64;
#elif defined(__AVX__)
    32;
#else
    16;
#endif

// The numbers of S in one register: 1 where S is not float or double.
template <class S>
inline constexpr std::size_t packet_width = std::is_floating_point_v<S>&& register_bytes > sizeof(S)
                                                ? register_bytes / sizeof(S)
                                                : 1;

template <class S, std::size_t V, bool Vector = std::is_floating_point_v<S>>
struct packet_of {
  using type = Eigen::Array<S, int(V), 1>;
};
#if defined(__GNUC__)
template <class S, std::size_t V>
struct packet_of<S, V, true> {
  typedef S type __attribute__((vector_size(sizeof(S) * V)));
};
#endif
// V numbers of S: + - * elementwise, * by a number of S, p[k] the k-th.
template <class S, std::size_t V>
using packet = typename packet_of<S, V>::type;

// V numbers all x
template <std::size_t V, class S>
KANE_ALWAYS_INLINE packet<S, V> splat(const S& x) {
  packet<S, V> p{};
  for (std::size_t k = 0; k < V; ++k) p[k] = x;
  return p;
}
// V numbers one after the other in memory, at any alignment
template <std::size_t V, class S>
KANE_ALWAYS_INLINE packet<S, V> load_packet(const S* from) {
  packet<S, V> p{};
  if constexpr (std::is_floating_point_v<S>)
    std::memcpy(&p, from, sizeof(p));
  else
    for (std::size_t k = 0; k < V; ++k) p[k] = from[k];
  return p;
}
template <std::size_t V, class S>
KANE_ALWAYS_INLINE void store_packet(const packet<S, V>& p, S* to) {
  if constexpr (std::is_floating_point_v<S>)
    std::memcpy(to, &p, sizeof(p));
  else
    for (std::size_t k = 0; k < V; ++k) to[k] = p[k];
}

// f(i, index_c<V>{}) for i from begin to end in steps of V: packets of W, then what is left in packets
// of W / 2, W / 4, ..., 1 (at most one of each)
template <std::size_t W, class F>
KANE_ALWAYS_INLINE void in_packets(std::size_t begin, std::size_t end, F&& f) {
  std::size_t i = begin;
  for (; i + W <= end; i += W) f(i, index_c<W>{});
  if constexpr (W > 1) in_packets<W / 2>(i, end, f);
}

}  // namespace kane::detail
