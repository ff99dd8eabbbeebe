// The inverse of a small fixed-size matrix by Gauss-Jordan elimination with
// full pivoting. Rank as Eigen's FullPivLU decides it: a pivot counts if it
// exceeds eps * n times the largest pivot (the first), or a given threshold.
// A 2 x 2 matrix is inverted in closed form under the same rule. The solves of a
// coupled block and of a positive definite system that jets overload.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace kane::detail {

// inv = m^-1 and true, or false if a pivot is not above tol (m finite). Rows
// of [m | I] are eliminated in place; exact zeros are skipped. tol < 0: the
// relative rule above.
template <class S, int N>
bool invert(const Eigen::Matrix<S, N, N>& m, Eigen::Matrix<S, N, N>& inv, S tol = S(-1)) {
  using std::abs;
  if constexpr (N == 2) {  // the same rule in closed form: pivots max |m_ij| and det / max |m_ij|
    const S a = m(0, 0), b = m(0, 1), c = m(1, 0), d = m(1, 1);
    const S ab = abs(a) > abs(b) ? abs(a) : abs(b), cd = abs(c) > abs(d) ? abs(c) : abs(d);
    const S best = ab > cd ? ab : cd, det = a * d - b * c;
    if (tol < S(0)) tol = std::numeric_limits<S>::epsilon() * S(2) * best;
    if (!(best > tol) || !(abs(det) > tol * best) || !(det - det == S(0))) return false;
    const S r = S(1) / det;
    inv << d * r, -b * r, -c * r, a * r;
    return true;
  }
  constexpr std::size_t n = static_cast<std::size_t>(N);  // array bounds are sizes
  S g[n][2 * n];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) g[i][j] = m(i, j), g[i][N + j] = S(i == j);
  int rows[n], cols[n];  // the rows and columns not pivoted yet: rows[0 .. N-k), cols[0 .. N-k)
  for (int i = 0; i < N; ++i) rows[i] = cols[i] = i;
  int row_of[n]{};  // row_of[c]: the row whose pivot eliminated column c
  for (int k = 0, left = N; k < N; ++k, --left) {
    int bi = 0, bj = 0;
    S best = S(-1);
    for (int i = 0; i < left; ++i)
      for (int j = 0; j < left; ++j)
        if (const S a = abs(g[rows[i]][cols[j]]); a > best) best = a, bi = i, bj = j;
    if (k == 0 && tol < S(0)) tol = std::numeric_limits<S>::epsilon() * S(N) * best;
    if (!(best > tol)) return false;
    const int r = rows[bi], c = cols[bj];
    rows[bi] = rows[left - 1], cols[bj] = cols[left - 1];
    row_of[c] = r;
    const S p = S(1) / g[r][c];
    for (S& x : g[r]) x *= p;
    for (int i = 0; i < N; ++i) {
      const S f = g[i][c];
      if (i == r || f == S(0)) continue;
      for (int j = 0; j < 2 * N; ++j) g[i][j] -= f * g[r][j];
    }
  }
  // [m | I] is now [P | m^-1 permuted]: g(row_of[c], c) = 1, so row c of m^-1 is row row_of[c].
  for (int c = 0; c < N; ++c)
    for (int j = 0; j < N; ++j) inv(c, j) = g[row_of[c]][N + j];
  return true;
}

// A coupled block B of a structured solve (block_solve.hpp): what the factorization keeps
// (B^-1) and y = B^-1 t. Jets overload both (jet.hpp).
template <class S, int N>
bool factor_block(const Eigen::Matrix<S, N, N>& b, Eigen::Matrix<S, N, N>& inv, S tol) {
  return invert(b, inv, tol);
}
template <class S, int N>
Eigen::Matrix<S, N, 1> solve_block(const Eigen::Matrix<S, N, N>& inv, const Eigen::Matrix<S, N, N>&,
                                   const Eigen::Matrix<S, N, 1>& t) {
  return inv * t;
}
// x = m^-1 f for a symmetric m by Cholesky (Eigen's LLT); false if m is not positive definite.
// Jets overload it (jet.hpp).
template <class S, int N>
bool solve_positive_definite(const Eigen::Matrix<S, N, N>& m, const Eigen::Matrix<S, N, 1>& f,
                             Eigen::Matrix<S, N, 1>& x) {
  const Eigen::LLT<Eigen::Matrix<S, N, N>> llt(m);
  if (llt.info() != Eigen::Success) return false;
  x = llt.solve(f);
  return true;
}

}  // namespace kane::detail
