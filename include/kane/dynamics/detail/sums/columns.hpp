// The kinds of partial velocity columns, known at compile time, and the sums that read them:
// a column v_r of a vector x in A's components is 0, +-e_i (a unit vector of A) or general.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/list.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/tables.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
// What each partial velocity v_r of x is at every state, in A's components: 0 (zero), +-(i + 1)
// (+-e_i: a unit vector of A, or of the root for A the root; the sums add a number to one
// component), or general_column. A void: the root of x's tree.
inline constexpr int general_column = 4;
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
template <class V, class A>
constexpr int column_kind() {
  if constexpr (is_zero_v<V> || is_zero_vector_v<V>)
    return 0;
  else if constexpr (unit_in<V, A>())
    return V::index;
  else if constexpr (is_vneg<V>::value) {
    using U = std::remove_cvref_t<decltype(std::declval<const V&>().v)>;
    if constexpr (unit_in<U, A>())
      return -U::index;
    else
      return general_column;
  } else
    return general_column;
}
template <class Sp, class X, class A = void>
constexpr std::array<int, Sp::n> nonzero_columns() {
  return []<std::size_t... R>(std::index_sequence<R...>) {
    return std::array<int, Sp::n>{
        column_kind<std::remove_cvref_t<decltype(column_of<Sp, R + 1>(std::declval<const X&>()))>, A>()...};
  }
  (std::make_index_sequence<Sp::n>{});
}
// out_r += v_r . x over the columns of the kinds K: +-x_i for +-e_i, nothing for 0 (for jets
// Eigen's product where no column is a unit vector).
template <auto K, class S, int N>
inline void add_transposed(Eigen::Matrix<S, N, 1>& out, const Eigen::Matrix<S, 3, N>& v,
                           const Eigen::Matrix<S, 3, 1>& x) {
  constexpr bool units = [] {
    for (int k : K)
      if (k != 0 && k != general_column) return true;
    return false;
  }();
  if constexpr (!units && !std::is_floating_point_v<S>)
    out.noalias() += v.transpose() * x;
  else
    static_for<std::size_t(N)>([&](auto r) {
      constexpr int k = K[r];
      if constexpr (k == general_column)
        out(Eigen::Index(r)) +=
            v(0, Eigen::Index(r)) * x(0) + v(1, Eigen::Index(r)) * x(1) + v(2, Eigen::Index(r)) * x(2);
      else if constexpr (k > 0)
        out(Eigen::Index(r)) += x(k - 1);
      else if constexpr (k < 0)
        out(Eigen::Index(r)) -= x(-k - 1);
    });
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
