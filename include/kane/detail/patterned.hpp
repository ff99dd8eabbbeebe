// Arithmetic with factors known at compile time to be 0 or 1 at every state
// (their entry, detail/structure.hpp: zero, one or other): such factors are not multiplied and
// such terms not added. A compiler cannot drop x * 0.0 or x + 0.0 itself (NaN,
// infinities and -0.0), and on jets it sees no constants at all.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "kane/detail/choices.hpp"
#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/structure.hpp"
#include "kane/detail/v3.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

constexpr entry entry_of_number(double c) {
  return c == 0.0 ? entry::zero : c == 1.0 ? entry::one : entry::other;
}

// x y, y of pattern Y
template <entry Y, class S>
KANE_ALWAYS_INLINE S times(const S& x, const S& y) {
  if constexpr (Y == entry::zero)
    return S(0);
  else if constexpr (Y == entry::one)
    return x;
  else
    return x * y;
}
// a x + b y and a x - b y, x and y of patterns X and Y
template <entry X, entry Y, class S>
KANE_ALWAYS_INLINE S plus(const S& a, const S& x, const S& b, const S& y) {
  if constexpr (Y == entry::zero)
    return times<X>(a, x);
  else if constexpr (X == entry::zero)
    return times<Y>(b, y);
  else
    return times<X>(a, x) + times<Y>(b, y);
}
template <entry X, entry Y, class S>
KANE_ALWAYS_INLINE S minus(const S& a, const S& x, const S& b, const S& y) {
  if constexpr (Y == entry::zero)
    return times<X>(a, x);
  else if constexpr (X == entry::zero)
    return -times<Y>(b, y);
  else
    return times<X>(a, x) - times<Y>(b, y);
}

// a b, a and b of patterns A and B
template <entry A, entry B, class S>
KANE_ALWAYS_INLINE S product(const S& a, const S& b) {
  if constexpr (A == entry::zero || B == entry::zero)
    return S(0);
  else if constexpr (A == entry::one)
    return B == entry::one ? S(1) : b;
  else
    return times<B>(a, b);
}
// x + a b and x - a b (x alone where a b is 0)
template <entry A, entry B, class S>
KANE_ALWAYS_INLINE S plus_product(const S& x, const S& a, const S& b) {
  if constexpr (A == entry::zero || B == entry::zero)
    return x;
  else
    return x + product<A, B>(a, b);
}
template <entry A, entry B, class S>
KANE_ALWAYS_INLINE S minus_product(const S& x, const S& a, const S& b) {
  if constexpr (A == entry::zero || B == entry::zero)
    return x;
  else
    return x - product<A, B>(a, b);
}
// k . x, k of pattern K
template <std::array<entry, 3> K, class S>
KANE_ALWAYS_INLINE S dot_along(const v3<S>& x, const v3<S>& k) {
  constexpr std::size_t first = K[0] != entry::zero   ? 0
                                : K[1] != entry::zero ? 1
                                : K[2] != entry::zero ? 2
                                                      : 3;
  if constexpr (first == 3)
    return S(0);
  else {
    S out = times<K[first]>(comp<first>(x), comp<first>(k));
    static_for<3>([&](auto j) {
      if constexpr (j > first) out = plus_product<entry::other, K[j]>(out, comp<j>(x), comp<j>(k));
    });
    return out;
  }
}
// A k, A symmetric (11 22 33 12 23 31), k of pattern K
template <std::array<entry, 3> K, class S>
KANE_ALWAYS_INLINE v3<S> symmetric_along(const std::array<S, 6>& a, const v3<S>& k) {
  return {dot_along<K>(v3<S>{a[0], a[3], a[5]}, k), dot_along<K>(v3<S>{a[3], a[1], a[4]}, k),
          dot_along<K>(v3<S>{a[5], a[4], a[2]}, k)};
}
// k x x, k of pattern K
template <std::array<entry, 3> K, class S>
KANE_ALWAYS_INLINE v3<S> cross_from(const v3<S>& k, const v3<S>& x) {
  return {minus<K[1], K[2]>(x.z, k.y, x.y, k.z), minus<K[2], K[0]>(x.x, k.z, x.z, k.x),
          minus<K[0], K[1]>(x.y, k.x, x.x, k.y)};
}
constexpr bool all_zero(const std::array<entry, 3>& k) {
  return k[0] == entry::zero && k[1] == entry::zero && k[2] == entry::zero;
}
// The pattern of r k: k's, its ones unknown.
constexpr std::array<entry, 3> scaled_pattern(const std::array<entry, 3>& k) {
  std::array<entry, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) out[i] = k[i] == entry::zero ? entry::zero : entry::other;
  return out;
}

// Whether the per-component forms below pay for S: a known 0 or 1, or a scalar whose operations
// the compiler does not see through (jets: the vector form makes temporaries).
template <class S, std::size_t N>
constexpr bool per_component(const std::array<entry, N>& pattern) {
  bool any_known = !std::is_floating_point_v<S>;
  for (entry x : pattern) any_known = any_known || x != entry::other;
  return any_known;
}
// x + r k, or r k onto zero, k of pattern K
template <std::array<entry, 3> K, onto To, class S>
KANE_ALWAYS_INLINE v3<S> add_along(const v3<S>& x, const S& r, const v3<S>& k) {
  const auto one = [&](const S& xi, auto i, const S& ki) -> S {
    if constexpr (To == onto::zero)
      return times<K[i]>(r, ki);
    else if constexpr (K[i] == entry::zero)
      return xi;
    else
      return xi + times<K[i]>(r, ki);
  };
  return {one(x.x, index_c<0>{}, k.x), one(x.y, index_c<1>{}, k.y), one(x.z, index_c<2>{}, k.z)};
}
// w x k, k of pattern K
template <std::array<entry, 3> K, class S>
KANE_ALWAYS_INLINE v3<S> cross_along(const v3<S>& w, const v3<S>& k) {
  return {minus<K[2], K[1]>(w.y, k.z, w.z, k.y), minus<K[0], K[2]>(w.z, k.x, w.x, k.z),
          minus<K[1], K[0]>(w.x, k.y, w.y, k.x)};
}

// e_Fp = e_Pp, e_Fa = c e_Pa + s e_Pb, e_Fb = c e_Pb - s e_Pa (a, b after p): the columns out of a
// frame turned about the principal axis p of its parent, whose columns in are of pattern P.
template <std::array<entry, 9> P, int p, class S>
KANE_ALWAYS_INLINE void turn_columns(S* out, const S* in, const S& c, const S& s) {
  constexpr int a = (p + 1) % 3, b = (p + 2) % 3;
  if constexpr (!per_component<S>(P)) {
    const v3<S> ea = load3(in + 3 * a), eb = load3(in + 3 * b);
    store3(out + 3 * p, load3(in + 3 * p));
    store3(out + 3 * a, c * ea + s * eb);
    store3(out + 3 * b, c * eb - s * ea);
  } else
    static_for<3>([&](auto i) {
      constexpr entry x = P[3 * a + i], y = P[3 * b + i];
      constexpr entry z = P[3 * p + i];
      out[3 * p + i] =
          z == entry::other ? in[3 * p + i] : S(z == entry::one);  // a known 0 or 1 written, not copied
      out[3 * a + i] = plus<x, y>(c, in[3 * a + i], s, in[3 * b + i]);
      out[3 * b + i] = minus<y, x>(c, in[3 * b + i], s, in[3 * a + i]);
    });
}

// Columns e_1, e_2, e_3 (9 numbers, column after column) turned about their own e_p:
// e_p stays, e_a = c e_a + s e_b and e_b = c e_b - s e_a mix (a, b the other two).
constexpr std::array<entry, 9> turned_columns(const std::array<entry, 9>& parent, int axis) {
  std::array<entry, 9> out{};
  const auto p = std::size_t(axis), a = (p + 1) % 3, b = (p + 2) % 3;
  for (std::size_t i = 0; i < 3; ++i) {
    out[3 * p + i] = parent[3 * p + i];
    out[3 * a + i] = out[3 * b + i] =
        parent[3 * a + i] == entry::zero && parent[3 * b + i] == entry::zero ? entry::zero : entry::other;
  }
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
