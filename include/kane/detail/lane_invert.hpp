// The inverse of a small coupled block on lanes (kane::lanes, scalars/lanes.hpp): the LU with full
// pivoting of invert.hpp in every lane at once. Each lane picks its own pivots by masks; rows and
// columns move by selects, so each lane takes the steps its state takes alone.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/invert.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// a and b exchanged in the lanes of s
template <class M, class L>
void swap_where(const M& s, L& a, L& b) {
  const L t = a;
  a = select(s, b, a), b = select(s, t, b);
}

// inv = m^-1 where every pivot exceeds tol (tol < 0: eps n times the first pivot), else NaN; the mask
// of the lanes where it holds. L: lanes of numbers, as kane::lanes.
template <class L, int N>
auto lane_invert(const Eigen::Matrix<L, N, N>& m, Eigen::Matrix<L, N, N>& inv, L tol) {
  using S = std::remove_cvref_t<decltype(m(0, 0)[0])>;
  constexpr std::size_t n = std::size_t(N);
  L a[n][n], p[n], q[n], r[n];  // P m Q = L U: row k of P m Q is row p[k] of m, column k column q[k]
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = q[i] = L(S(i));
    for (std::size_t j = 0; j < n; ++j) a[i][j] = m(Eigen::Index(i), Eigen::Index(j));
  }
  auto ok = L(S(0)) == L(S(0));
#pragma GCC unroll 8
  for (std::size_t k = 0; k < n; ++k) {
    L best = L(S(-1)), bi = L(S(k)), bj = L(S(k));  // the first largest |a_ij| left, as invert.hpp
    for (std::size_t i = k; i < n; ++i)
      for (std::size_t j = k; j < n; ++j) {
        const L x = abs(a[i][j]);
        const auto larger = x > best;
        best = select(larger, x, best), bi = select(larger, L(S(i)), bi), bj = select(larger, L(S(j)), bj);
      }
    if (k == 0) tol = select(tol < L(S(0)), L(std::numeric_limits<S>::epsilon() * S(N)) * best, tol);
    ok = ok && best > tol;
    for (std::size_t i = k + 1; i < n; ++i) {
      const auto s = bi == L(S(i));
      for (std::size_t j = 0; j < n; ++j) swap_where(s, a[k][j], a[i][j]);
      swap_where(s, p[k], p[i]);
    }
    for (std::size_t j = k + 1; j < n; ++j) {
      const auto s = bj == L(S(j));
      for (std::size_t i = 0; i < n; ++i) swap_where(s, a[i][k], a[i][j]);
      swap_where(s, q[k], q[j]);
    }
    r[k] = L(S(1)) / a[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      const L l = a[i][k] * r[k];
      a[i][k] = l;
      for (std::size_t j = k + 1; j < n; ++j) a[i][j] -= l * a[k][j];
    }
  }
  const L nan = L(std::numeric_limits<S>::quiet_NaN());
#pragma GCC unroll 8
  for (std::size_t c = 0; c < n; ++c) {  // column c of m^-1: L z = P e_c, U y = z, x = Q y
    L y[n];
    for (std::size_t i = 0; i < n; ++i) y[i] = select(p[i] == L(S(c)), L(S(1)), L(S(0)));
    lu_substitute(a, r, y);
    for (std::size_t row = 0; row < n; ++row) {  // x_q[i] = y_i: one i per lane
      L x = y[0];
      for (std::size_t i = 1; i < n; ++i) x = select(q[i] == L(S(row)), y[i], x);
      inv(Eigen::Index(row), Eigen::Index(c)) = select(ok, x, nan);
    }
  }
  return ok;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
