// sin and cos of the coordinates a computation needs, each computed once.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace kane::detail {

template <class S, std::size_t NQ>
struct trig {
  std::array<S, NQ> s{};
  std::array<S, NQ> c{};
  S sin(std::size_t i) const { return s[i - 1]; }  // sin q_i
  S cos(std::size_t i) const { return c[i - 1]; }  // cos q_i
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

// sin/cos of q_k for k in Needed (a std::array of 1-based indices).
template <auto Needed, class State>
auto make_trig(const State& st) {
  using S = typename State::scalar;
  static_assert(Needed.empty() || Needed.back() <= State::nq,
                "kane: the frames involved use a generalized coordinate beyond the state's size; "
                "declare the state with at least that many coordinates");
  trig<S, State::nq> t;
  for (std::size_t k : Needed) {
    using std::cos;
    using std::sin;
    t.s[k - 1] = sin(st.q[k - 1]);
    t.c[k - 1] = cos(st.q[k - 1]);
  }
  return t;
}

}  // namespace kane::detail
