// sin and cos of the coordinates a computation needs, each computed once and
// stored only for those (Needed: ascending 1-based indices, known at compile time).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"

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

// sin/cos of q_k for k in Needed.
template <auto Needed, class State>
KANE_ALWAYS_INLINE trig<typename State::scalar, Needed> make_trig(const State& st) {
  static_assert(Needed.empty() || Needed.back() <= State::nq,
                "kane: the frames involved use a generalized coordinate beyond the state's size; "
                "declare the state with at least that many coordinates");
  trig<typename State::scalar, Needed> t;
  [&]<std::size_t... K>(std::index_sequence<K...>) {  // unrolled at -O2 too
    using std::cos;
    using std::sin;
    // the angles read before the first call: a call may change a state that is not a local
    [[maybe_unused]] const std::array<typename State::scalar, sizeof...(K)> q{st.q[Needed[K] - 1]...};
    ((t.s[K] = sin(q[K]), t.c[K] = cos(q[K])), ...);
  }
  (std::make_index_sequence<Needed.size()>{});
  return t;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
