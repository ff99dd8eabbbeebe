// Three components by value: the evaluators' working vector. Plain scalars
// stay in registers; fixed-size Eigen temporaries returned through deep
// expression trees went through the stack (store-forwarding stalls).
#pragma once

#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"

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

template <class S>
struct v3 {
  S x, y, z;
};

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
constexpr v3<S> load3(const S* p) {
  return {p[0], p[1], p[2]};
}
template <class S>
constexpr void store3(S* p, const v3<S>& a) {
  p[0] = a.x, p[1] = a.y, p[2] = a.z;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
