// sin and cos of the coordinates a computation needs, each computed once and
// stored only for those (Needed: ascending 1-based indices, known at compile time).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_math.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/packet.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S, auto Needed>
struct trig {
  static constexpr std::size_t size = Needed.size();
  std::array<S, size> s, c;  // written by make_trig
  template <std::size_t I>
  static constexpr std::size_t slot() {
    static_assert(holds<I>(), "kane: sin and cos of this coordinate were not computed");
    std::size_t k = 0;
    while (Needed[k] != I) ++k;
    return k;
  }
  template <std::size_t I>
  static constexpr bool holds() {
    for (std::size_t k : Needed)
      if (k == I) return true;
    return false;
  }
  template <std::size_t I>
  S sin() const {
    return s[slot<I>()];
  }
  template <std::size_t I>
  S cos() const {
    return c[slot<I>()];
  }
};

template <std::size_t N>
constexpr std::size_t count_unique(const std::array<std::size_t, N>& a) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < N; ++i) {
    bool seen = false;
    for (std::size_t j = 0; j < i; ++j) seen = seen || a[j] == a[i];
    n += seen ? 0 : 1;
  }
  return n;
}

// The indices Ks..., each once, ascending.
template <std::size_t... Ks>
constexpr auto unique_indices() {
  constexpr std::array<std::size_t, sizeof...(Ks)> all{Ks...};
  std::array<std::size_t, count_unique(all)> out{};
  std::size_t n = 0;
  for (std::size_t v = 0; n < out.size(); ++v)
    for (std::size_t k : all)
      if (k == v) {
        out[n++] = v;
        break;
      }
  return out;
}

// The indices Ks... but 0, each once, ascending (0: an edge whose angle is not a bare coordinate).
template <std::size_t... Ks>
constexpr auto coordinate_indices() {
  constexpr auto all = unique_indices<Ks...>();
  constexpr std::size_t n = all.size() > 0 && all[0] == 0 ? all.size() - 1 : all.size();
  std::array<std::size_t, n> out{};
  for (std::size_t i = 0; i < n; ++i) out[i] = all[all.size() - n + i];
  return out;
}

// The coordinates whose sin and cos the frames of a closure (list<F...>) read: the bare ones.
template <class L>
struct step_coordinates;
template <class... F>
struct step_coordinates<list<F...>> {
  template <class X>
  static constexpr std::size_t index() {
    if constexpr (std::is_void_v<typename X::tree_parent>)
      return 0;
    else
      return X::step::coordinate_index;
  }
  static constexpr auto value = coordinate_indices<index<F>()...>();
};

// sin and cos of the angles a[0..N) into s and c: W at a time in vector registers (lane_math.hpp).
template <std::size_t W, class S, std::size_t N>
KANE_ALWAYS_INLINE void vector_sincos(const std::array<S, N>& a, std::array<S, N>& s, std::array<S, N>& c) {
  using vector = packet<S, W>;
  [&]<std::size_t... B>(std::index_sequence<B...>) KANE_ALWAYS_INLINE_LAMBDA {
    (
        [&]() KANE_ALWAYS_INLINE_LAMBDA {
          vector x{}, vs, vc;
          for (std::size_t k = 0; k < W && B * W + k < N; ++k) x[k] = a[B * W + k];
          lane_sincos<S, W>(x, vs, vc);
          for (std::size_t k = 0; k < W && B * W + k < N; ++k) s[B * W + k] = vs[k], c[B * W + k] = vc[k];
        }(),
        ...);
  }
  (std::make_index_sequence<(N + W - 1) / W>{});
}

// sin/cos of q_k for k in Needed: for float and double on x86, all at once in vector registers
// (within an ulp or two of std::sin and std::cos, as kane::lanes); else by std::sin and std::cos.
template <auto Needed, class State>
KANE_ALWAYS_INLINE trig<typename State::scalar, Needed> make_trig(const State& st) {
  using S = typename State::scalar;
  static_assert(Needed.empty() || Needed.back() <= State::nq,
                "kane: the frames involved use a generalized coordinate beyond the state's size; "
                "declare the state with at least that many coordinates");
  constexpr std::size_t n = Needed.size();
  trig<S, Needed> t;
  [&]<std::size_t... K>(std::index_sequence<K...>) {  // unrolled at -O2 too
    using std::cos;
    using std::sin;
    // the angles read before the first call: a call may change a state that is not a local
    [[maybe_unused]] const std::array<S, sizeof...(K)> q{st.q[Needed[K] - 1]...};
#if defined(__SSE2__) && defined(__GNUC__) && !defined(KANE_STD_TRIG)
    if constexpr (n > 0 && std::is_floating_point_v<S> && !std::is_same_v<S, long double>) {
      constexpr std::size_t w = packet_width<S>, all = std::bit_ceil(n);
      vector_sincos<(all < w ? all : w)>(q, t.s, t.c);
      return;
    }
#endif
    ((t.s[K] = sin(q[K]), t.c[K] = cos(q[K])), ...);
  }
  (std::make_index_sequence<n>{});
  return t;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
