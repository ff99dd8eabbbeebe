// M known at compile time: every mass and inertia of the system a known number, every partial
// velocity of a mass centre constant in the root or in its body's frame, every partial angular
// velocity constant in its inertia's frame, with known components (a free body about its mass
// centre with body rates and q' as speeds, a gyrostat, a top on body rates). Then
// M_rs = sum m v_r . v_s + w_r . I . w_s is a table of numbers, and so is M^-1 (LDL^T in a
// constant expression): u' = M^-1 f multiplies by its nonzero entries alone.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/sums/columns.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/tree/fixed_vectors.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
// an N x N table by rows; known: every entry a number of the code (M), or definite (M^-1)
template <std::size_t N>
struct known_table {
  bool known = true;
  std::array<double, N * N> m{};
};
template <class... C>
constexpr bool known_scalars(std::type_identity<std::tuple<C...>>) {
  return (known_scalar<C>() && ...);
}
// The partial velocities of x in F's components, if known: 0, +-e_i of F (or of the root for F the
// root), or constant multiples of F's unit vectors with known factors.
template <std::size_t N>
struct known_columns {
  bool known = true;
  std::array<std::array<double, 3>, N> c{};
};
template <class Sp, class F, class X>
constexpr known_columns<Sp::n> columns_known_in(const X& x) {
  constexpr auto k = nonzero_columns<Sp, X, F>();
  known_columns<Sp::n> out;
  [&]<std::size_t... R>(std::index_sequence<R...>) {
    (
        [&] {
          using C = std::remove_cvref_t<decltype(column_of<Sp, R + 1>(x))>;
          constexpr int i = column_axis(k[R]);
          if constexpr (all_zero(k[R]))
            return;
          else if constexpr (i >= 0)
            out.c[R][std::size_t(i)] = k[R][std::size_t(i)] == entry::one ? 1 : -1;
          else if constexpr (std::is_same_v<typename fixed_frame_of<C>::type, F> && known_vector<C>())
            out.c[R] = known_components(column_of<Sp, R + 1>(x));
          else
            out.known = false;
        }(),
        ...);
  }
  (std::make_index_sequence<Sp::n>{});
  return out;
}
template <std::size_t N, class W>
constexpr void add_products(known_table<N>& out, const known_columns<N>& v, const W& weight) {
  std::array<bool, N> nonzero{};
  for (std::size_t r = 0; r < N; ++r) nonzero[r] = v.c[r][0] != 0 || v.c[r][1] != 0 || v.c[r][2] != 0;
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t s = 0; s < N && nonzero[r]; ++s)
      for (std::size_t i = 0; i < 3 && nonzero[s]; ++i)
        for (std::size_t j = 0; j < 3; ++j) out.m[r * N + s] += v.c[r][i] * weight(i, j) * v.c[s][j];
}
// the terms of item X; none once an item has made M unknown
template <class R, class Sp, class X>
constexpr void add_known_terms(known_table<Sp::n>& out) {
  if (!out.known) return;
  if constexpr (is_particle<X> || is_body<X>) {
    using P = typename point_of_mass<X>::type;
    constexpr auto v = [] {  // in the root, else in the body's frame
      constexpr auto in_root = columns_known_in<Sp, R>(velocity<R, P>());
      if constexpr (is_body<X> && !in_root.known)
        return columns_known_in<Sp, typename X::frame>(velocity<R, P>());
      else
        return in_root;
    }();
    if constexpr (!known_scalar<std::remove_cv_t<decltype(X::mass)>>() || !v.known)
      out.known = false;
    else {
      constexpr double m = known_value(X::mass);
      add_products(out, v, [](std::size_t i, std::size_t j) { return i == j ? m : 0.0; });
    }
    if constexpr (is_body<X>) {
      using I = typename X::inertia_type;
      constexpr auto w = columns_known_in<Sp, typename I::frame>(angular_velocity<R, typename X::frame>());
      constexpr auto c = I::components;
      if constexpr (!known_scalars(std::type_identity<std::remove_cv_t<decltype(c)>>{}) || !w.known)
        out.known = false;
      else {
        constexpr std::array<double, 6> i = [&]<std::size_t... J>(std::index_sequence<J...>) {
          return std::array<double, 6>{known_value(std::get<J>(c))...};
        }
        (std::make_index_sequence<6>{});
        add_products(out, w, [&](std::size_t a, std::size_t b) { return i[sym_index[a][b]]; });
      }
    }
  }
}
// M of Sys over the speeds Sp in the root R, if known (known_table::known)
template <class Sys, class R, class Sp>
inline constexpr known_table<Sp::n> known_mass_matrix = []<class... X>(list<X...>) {
  known_table<Sp::n> out;
  (add_known_terms<R, Sp, X>(out), ...);
  return out;
}(typename Sys::items{});
// M^-1 by M = L D L^T; known: M is positive definite (no pivot d_j <= 0)
template <std::size_t N>
constexpr known_table<N> inverse_of(const known_table<N>& a) {
  known_table<N> out;
  std::array<double, N * N> l{};
  std::array<double, N> d{};
  for (std::size_t j = 0; j < N; ++j) {
    d[j] = a.m[j * N + j];
    for (std::size_t k = 0; k < j; ++k) d[j] -= l[j * N + k] * l[j * N + k] * d[k];
    if (!(d[j] > 0)) {
      out.known = false;
      return out;
    }
    l[j * N + j] = 1;
    for (std::size_t i = j + 1; i < N; ++i) {
      double s = a.m[i * N + j];
      for (std::size_t k = 0; k < j; ++k) s -= l[i * N + k] * l[j * N + k] * d[k];
      l[i * N + j] = s / d[j];
    }
  }
  for (std::size_t c = 0; c < N; ++c) {  // column c: L y = e_c, then L^T x = D^-1 y
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) {
      y[i] = i == c ? 1 : 0;
      for (std::size_t k = 0; k < i; ++k) y[i] -= l[i * N + k] * y[k];
    }
    for (std::size_t i = N; i-- > 0;) {
      double x = y[i] / d[i];
      for (std::size_t k = i + 1; k < N; ++k) x -= l[k * N + i] * out.m[k * N + c];
      out.m[i * N + c] = x;
    }
  }
  return out;
}
template <class Sys, class R, class Sp>
inline constexpr known_table<Sp::n> known_inverse = [] {
  if constexpr (known_mass_matrix<Sys, R, Sp>.known)
    return inverse_of(known_mass_matrix<Sys, R, Sp>);
  else
    return known_table<Sp::n>{false, {}};
}();
template <std::size_t N>
constexpr std::size_t first_nonzero(const known_table<N>& t, std::size_t r) {  // in row r, or N
  std::size_t c = 0;
  while (c < N && t.m[r * N + c] == 0) ++c;
  return c;
}
// x = T b for a table T of numbers: its zeros cost nothing. x is stored in blocks
// (detail/wide_stores.hpp).
template <auto T, class S, int N>
KANE_ALWAYS_INLINE Eigen::Matrix<S, N, 1> times_known(const Eigen::Matrix<S, N, 1>& b) {
  constexpr std::size_t n = std::size_t(N);
  Eigen::Matrix<S, N, 1> x;
  store_in_blocks<n>(x.data(), [&](auto r) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t first = first_nonzero(T, r);
    S sum = S(0);
    static_for_inline<n>([&](auto c) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t I = r * n + c;
      if constexpr (c == first)
        sum = S(T.m[I]) * b(Eigen::Index(c));
      else if constexpr (c > first && T.m[I] != 0)
        sum += S(T.m[I]) * b(Eigen::Index(c));
    });
    return sum;
  });
  return x;
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
