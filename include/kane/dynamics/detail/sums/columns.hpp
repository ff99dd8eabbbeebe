// What partial velocity columns are at every state, known at compile time, and the sums that read
// them: a column v_r of a vector x in A's components is 0, +-e_i (a unit vector of A) or general.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/lane_traits.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/tables.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
// What each partial velocity v_r of x is at every state, in A's components: 0, +-e_i (a unit vector of
// A, or of the root for A the root: entry one or minus_one at i, zero elsewhere), or general with
// the components known to be zero (zeros_in).
// A void: the root of x's tree.
constexpr pattern3 unit_pattern(int i, entry e) {
  pattern3 p{entry::zero, entry::zero, entry::zero};
  p[std::size_t(i)] = e;
  return p;
}
// The axis i of a column +-e_i, or -1.
constexpr int column_axis(const pattern3& k) {
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    const entry e = k[std::size_t(i)];
    if (e == entry::one || e == entry::minus_one) {
      if (axis >= 0) return -1;
      axis = i;
    } else if (e != entry::zero)
      return -1;
  }
  return axis;
}
template <class V, class A>
constexpr bool unit_in() {
  if constexpr (!is_unit<V>::value)
    return false;
  else if constexpr (std::is_void_v<A>)
    return root_unit<V>::value;
  else if constexpr (std::is_void_v<typename A::tree_parent>)
    return root_unit<V>::value;
  else
    return std::is_same_v<typename V::frame, A> || std::is_same_v<lifted_t<typename V::frame, V::index>, A>;
}
// The zeros of a general column in A's components (the root's for A void or the root).
template <class V, class A>
constexpr pattern3 column_zeros() {
  if constexpr (std::is_void_v<A>)
    return zeros_in<void, V>();
  else if constexpr (std::is_void_v<typename A::tree_parent>)
    return zeros_in<void, V>();
  else
    return zeros_in<A, V>();
}
template <class V, class A>
constexpr pattern3 column_kind() {
  if constexpr (is_zero_v<V> || is_zero_vector_v<V>)
    return {entry::zero, entry::zero, entry::zero};
  else if constexpr (unit_in<V, A>())
    return unit_pattern(V::index - 1, entry::one);
  else if constexpr (is_vneg<V>::value) {
    using U = std::remove_cvref_t<decltype(std::declval<const V&>().v)>;
    if constexpr (unit_in<U, A>())
      return unit_pattern(U::index - 1, entry::minus_one);
    else
      return column_zeros<V, A>();
  } else
    return column_zeros<V, A>();
}
template <class Sp, class X, class A = void>
constexpr std::array<pattern3, Sp::n> nonzero_columns() {
  return []<std::size_t... R>(std::index_sequence<R...>) {
    return std::array<pattern3, Sp::n>{
        column_kind<std::remove_cvref_t<decltype(column_of<Sp, R + 1>(std::declval<const X&>()))>, A>()...};
  }
  (std::make_index_sequence<Sp::n>{});
}
// the zeros of a component-wise product: those of either factor
constexpr pattern3 product_zeros(const pattern3& a, const pattern3& b) {
  pattern3 z = unknown3;
  for (std::size_t i = 0; i < 3; ++i)
    if (a[i] == entry::zero || b[i] == entry::zero) z[i] = entry::zero;
  return z;
}
// a . b over the components that k does not know to be zero
template <pattern3 K, class A, class B>
KANE_ALWAYS_INLINE auto dot_where(const A& a, const B& b) {
  using S = std::remove_cvref_t<decltype(a(0) * b(0))>;
  constexpr bool x = K[0] != entry::zero, y = K[1] != entry::zero, z = K[2] != entry::zero;
  if constexpr (x && y && z)
    return S(a(0) * b(0) + a(1) * b(1) + a(2) * b(2));
  else if constexpr (x && y)
    return S(a(0) * b(0) + a(1) * b(1));
  else if constexpr (x && z)
    return S(a(0) * b(0) + a(2) * b(2));
  else if constexpr (y && z)
    return S(a(1) * b(1) + a(2) * b(2));
  else
    return S(x ? a(0) * b(0) : y ? a(1) * b(1) : a(2) * b(2));
}
// out_r += v_r . x over the columns of the kinds K: +-x_i for +-e_i, nothing for 0 (for jets
// Eigen's product where no column is a unit vector).
template <auto K, class S, int N>
inline void add_transposed(Eigen::Matrix<S, N, 1>& out, const Eigen::Matrix<S, 3, N>& v,
                           const Eigen::Matrix<S, 3, 1>& x) {
  constexpr bool units = [] {
    for (const pattern3& k : K)
      if (column_axis(k) >= 0) return true;
    return false;
  }();
  if constexpr (!units && !std::is_floating_point_v<S> && lane_traits<S>::width == 1)
    out.noalias() += v.transpose() * x;
  else
    static_for<std::size_t(N)>([&](auto r) {
      constexpr pattern3 k = K[r];
      constexpr int i = column_axis(k);
      if constexpr (all_zero(k))
        return;
      else if constexpr (i < 0)
        out(Eigen::Index(r)) += dot_where<k>(v.col(Eigen::Index(r)), x);
      else if constexpr (k[std::size_t(i)] == entry::one)
        out(Eigen::Index(r)) += x(i);
      else
        out(Eigen::Index(r)) -= x(i);
    });
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
