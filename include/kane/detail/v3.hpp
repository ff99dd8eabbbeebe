// Three components by value: the evaluators' working vector. Plain scalars
// stay in registers; fixed-size Eigen temporaries returned through deep
// expression trees went through the stack (store-forwarding stalls).
#pragma once

#include <limits>
#include <type_traits>

#include "kane/detail/inline.hpp"

namespace kane::detail {

// An array (of arrays) of S with every number NaN: caches before their first write.
template <class A>
constexpr A nan_filled() {
  A a{};
  for (auto& x : a) {
    if constexpr (requires { x.size(); })
      x = nan_filled<std::remove_cvref_t<decltype(x)>>();
    else
      x = std::numeric_limits<std::remove_cvref_t<decltype(x)>>::quiet_NaN();
  }
  return a;
}

template <class S>
struct v3 {
  S x, y, z;
};

template <class S>
constexpr v3<S> operator+(const v3<S>& a, const v3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class S>
constexpr v3<S> operator-(const v3<S>& a, const v3<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class S>
constexpr v3<S> operator-(const v3<S>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class S>
constexpr v3<S> operator*(const S& s, const v3<S>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class S>
constexpr v3<S> cross3(const v3<S>& a, const v3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class S>
constexpr S dot3(const v3<S>& a, const v3<S>& b) {
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
