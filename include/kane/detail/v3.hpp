// Three components by value: the evaluators' working vector. Plain scalars
// stay in registers; fixed-size Eigen temporaries returned through deep
// expression trees went through the stack (store-forwarding stalls).
#pragma once

#include <array>

#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/structure.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// Every number of a (an array of arrays of S) NaN, one store each: caches
// before their first write. Not a block copy of a constant: the update that
// follows a construction overwrites each number, and the optimiser drops the
// stores it kills one by one (it keeps a copy of over 256 bytes whole).
template <class A, std::size_t... I>
KANE_ALWAYS_INLINE constexpr void fill_nan(A& a, std::index_sequence<I...>) {
  if constexpr (requires { a[0].size(); })
    (fill_nan(a[I], std::make_index_sequence<std::tuple_size_v<std::remove_cvref_t<decltype(a[0])>>>{}), ...);
  else
    ((a[I] = std::numeric_limits<std::remove_cvref_t<decltype(a[0])>>::quiet_NaN()), ...);
}
template <class A>
KANE_ALWAYS_INLINE constexpr void fill_nan(A& a) {
  fill_nan(a, std::make_index_sequence<std::tuple_size_v<A>>{});
}

// A symmetric 3 x 3 matrix as six numbers: 11 22 33 12 23 31 (kane::inertia's order), and the
// entry of row j, column k among them.
template <class S>
using sym3 = std::array<S, 6>;
inline constexpr std::size_t sym_index[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

template <class S>
struct v3 {
  S x, y, z;
};
// A 3 x 3 matrix by its rows.
template <class S>
using m3 = std::array<v3<S>, 3>;

template <class S>
KANE_ALWAYS_INLINE constexpr v3<S> operator+(const v3<S>& a, const v3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class S>
KANE_ALWAYS_INLINE constexpr v3<S> operator-(const v3<S>& a, const v3<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class S>
KANE_ALWAYS_INLINE constexpr v3<S> operator-(const v3<S>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class S>
KANE_ALWAYS_INLINE constexpr v3<S> operator*(const S& s, const v3<S>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class S>
KANE_ALWAYS_INLINE constexpr v3<S> cross3(const v3<S>& a, const v3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class S>
KANE_ALWAYS_INLINE constexpr S dot3(const v3<S>& a, const v3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class S>
KANE_ALWAYS_INLINE constexpr sym3<S> operator+(const sym3<S>& a, const sym3<S>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3], a[4] + b[4], a[5] + b[5]};
}
template <class S>
KANE_ALWAYS_INLINE constexpr m3<S> operator+(const m3<S>& a, const m3<S>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
// Component I (0, 1, 2) of a (a v3, const or not): the one accessor of a v3's components.
template <std::size_t I, class V>
KANE_ALWAYS_INLINE constexpr auto& comp(V& a) {
  static_assert(I < 3, "kane: a v3 has components 0, 1, 2");
  if constexpr (I == 0)
    return a.x;
  else if constexpr (I == 1)
    return a.y;
  else
    return a.z;
}
// The operations with components known to be zero (Za, Zb: the patterns of a, b; their zeros
// only): those terms are not formed, since the optimizer keeps s * 0 and x + 0 (NaN, inf and -0
// forbid folding).
using pattern3 = std::array<entry, 3>;
inline constexpr pattern3 unknown3{entry::other, entry::other, entry::other};
constexpr bool any_zero(const pattern3& z) {
  return z[0] == entry::zero || z[1] == entry::zero || z[2] == entry::zero;
}
template <pattern3 Z, int I, class S>
KANE_ALWAYS_INLINE constexpr S part(const v3<S>& a) {
  if constexpr (Z[I] == entry::zero)
    return S(0);
  else
    return comp<std::size_t(I)>(a);
}
template <pattern3 Za, pattern3 Zb, int I, class S>
KANE_ALWAYS_INLINE constexpr S sum_part(const v3<S>& a, const v3<S>& b) {
  if constexpr (Za[I] == entry::zero)
    return part<Zb, I>(b);
  else if constexpr (Zb[I] == entry::zero)
    return part<Za, I>(a);
  else
    return part<Za, I>(a) + part<Zb, I>(b);
}
template <pattern3 Za, pattern3 Zb, class S>
KANE_ALWAYS_INLINE constexpr v3<S> add_known(const v3<S>& a, const v3<S>& b) {
  if constexpr (!any_zero(Za) && !any_zero(Zb))  // the common case: nothing to instantiate
    return a + b;
  else
    return {sum_part<Za, Zb, 0>(a, b), sum_part<Za, Zb, 1>(a, b), sum_part<Za, Zb, 2>(a, b)};
}
template <pattern3 Za, pattern3 Zb, int I, class S>
KANE_ALWAYS_INLINE constexpr S difference_part(const v3<S>& a, const v3<S>& b) {
  if constexpr (Zb[I] == entry::zero)
    return part<Za, I>(a);
  else
    return part<Za, I>(a) - part<Zb, I>(b);  // 0 - y, not -y: the sign of a zero as before
}
template <pattern3 Za, pattern3 Zb, class S>
KANE_ALWAYS_INLINE constexpr v3<S> subtract_known(const v3<S>& a, const v3<S>& b) {
  if constexpr (!any_zero(Za) && !any_zero(Zb))
    return a - b;
  else
    return {difference_part<Za, Zb, 0>(a, b), difference_part<Za, Zb, 1>(a, b),
            difference_part<Za, Zb, 2>(a, b)};
}
template <pattern3 Z, int I, class S>
KANE_ALWAYS_INLINE constexpr S scaled_part(const S& s, const v3<S>& a) {
  if constexpr (Z[I] == entry::zero)
    return S(0);
  else
    return s * part<Z, I>(a);
}
template <pattern3 Z, class S>
KANE_ALWAYS_INLINE constexpr v3<S> scale_known(const S& s, const v3<S>& a) {
  if constexpr (!any_zero(Z))
    return s * a;
  else
    return {scaled_part<Z, 0>(s, a), scaled_part<Z, 1>(s, a), scaled_part<Z, 2>(s, a)};
}
// The zeros of a x b: component i = a_j b_k - a_k b_j, (i, j, k) cyclic.
constexpr bool product_zero(const pattern3& za, const pattern3& zb, int j, int k) {
  return za[std::size_t(j)] == entry::zero || zb[std::size_t(k)] == entry::zero;
}
constexpr pattern3 cross_zeros(const pattern3& za, const pattern3& zb) {
  pattern3 z = unknown3;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (product_zero(za, zb, j, k) && product_zero(za, zb, k, j)) z[std::size_t(i)] = entry::zero;
  }
  return z;
}
// Za and Zb: the zeros common to both.
constexpr pattern3 common_zeros(const pattern3& za, const pattern3& zb) {
  pattern3 z = unknown3;
  for (std::size_t i = 0; i < 3; ++i)
    if (za[i] == entry::zero && zb[i] == entry::zero) z[i] = entry::zero;
  return z;
}
template <pattern3 Za, pattern3 Zb, int I, class S>
KANE_ALWAYS_INLINE constexpr S cross_part(const v3<S>& a, const v3<S>& b) {
  constexpr int j = (I + 1) % 3, k = (I + 2) % 3;
  constexpr bool first = !product_zero(Za, Zb, j, k), second = !product_zero(Za, Zb, k, j);
  if constexpr (first && second)
    return part<Za, j>(a) * part<Zb, k>(b) - part<Za, k>(a) * part<Zb, j>(b);
  else if constexpr (first)
    return part<Za, j>(a) * part<Zb, k>(b);
  else if constexpr (second)
    return -(part<Za, k>(a) * part<Zb, j>(b));
  else
    return S(0);
}
template <pattern3 Za, pattern3 Zb, class S>
KANE_ALWAYS_INLINE constexpr v3<S> cross_known(const v3<S>& a, const v3<S>& b) {
  if constexpr (!any_zero(Za) && !any_zero(Zb))
    return cross3(a, b);
  else
    return {cross_part<Za, Zb, 0>(a, b), cross_part<Za, Zb, 1>(a, b), cross_part<Za, Zb, 2>(a, b)};
}

template <class S>
constexpr v3<S> load3(const S* p) {
  return {p[0], p[1], p[2]};
}
template <class S>
constexpr void store3(S* p, const v3<S>& a) {
  p[0] = a.x, p[1] = a.y, p[2] = a.z;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
