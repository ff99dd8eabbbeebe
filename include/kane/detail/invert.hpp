// The inverse of a small fixed-size matrix by Gauss-Jordan elimination with
// full pivoting. Rank as Eigen's FullPivLU decides it: a pivot counts if it
// exceeds eps * n times the largest pivot (the first).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace kane::detail {

// inv = m^-1 and true, or false if m is singular (m finite).
template <class S, int N>
bool invert(Eigen::Matrix<S, N, N> a, Eigen::Matrix<S, N, N>& inv) {
  using std::abs;
  inv.setIdentity();
  std::array<bool, N> row_used{}, col_used{};
  std::array<int, N> row_of{};  // row_of[c]: the row whose pivot eliminated column c
  const S threshold = std::numeric_limits<S>::epsilon() * S(N);
  S first = S(0);
  for (int k = 0; k < N; ++k) {
    int r = 0, c = 0;
    S best = S(-1);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (!row_used[i] && !col_used[j] && abs(a(i, j)) > best) best = abs(a(i, j)), r = i, c = j;
    if (k == 0) first = best;
    if (!(best > threshold * first)) return false;
    row_used[r] = col_used[c] = true;
    row_of[c] = r;
    const S p = S(1) / a(r, c);
    a.row(r) *= p;
    inv.row(r) *= p;
    for (int i = 0; i < N; ++i)
      if (i != r) {
        const S f = a(i, c);
        a.row(i) -= f * a.row(r);
        inv.row(i) -= f * inv.row(r);
      }
  }
  // a is now a permutation: a(row_of[c], c) = 1, so x_c = inv.row(row_of[c]).
  const Eigen::Matrix<S, N, N> b = inv;
  for (int c = 0; c < N; ++c) inv.row(c) = b.row(row_of[c]);
  return true;
}

}  // namespace kane::detail
