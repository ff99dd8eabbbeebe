// The eigenvalues of a small real square matrix of compile-time size, as the stability of a
// linearization asks (A of linearize, or [0 1; -M^-1 K, -M^-1 C] of linearize_equations):
//
//   const auto [lambda, status] = kane::eigenvalues(A);
//
// Balancing by powers of 2, reduction to Hessenberg form by eliminations with pivots, then
// Francis's double-shift QR with deflation (EISPACK's balanc, elmhes and hqr; Wilkinson and
// Reinsch, Handbook for Automatic Computation II, 1971). Values sorted by real part, then
// imaginary part; a complex pair as conjugates. No heap, no exceptions; not_finite for input
// that is not, not_converged after `sweeps` QR steps on one eigenvalue (30 unless given), and
// NaN values with either.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/evaluation/status.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// The eigenvalues of an N x N real matrix and how the iteration ended.
template <class S, int N>
struct spectrum {
  Eigen::Matrix<std::complex<S>, N, 1> values;
  solve_status status;
};

namespace detail {
template <class S, int N>
using square = std::array<std::array<S, std::size_t(N)>, std::size_t(N)>;

// Rows and columns scaled by powers of 2 until their norms are near: the same eigenvalues.
template <class S, int N>
void balance(square<S, N>& a) {
  constexpr S radix = 2, sq = radix * radix;
  bool done = false;
  for (int sweep = 0; sweep < 64 && !done; ++sweep) {
    done = true;
    for (std::size_t i = 0; i < std::size_t(N); ++i) {
      S c = 0, r = 0;
      for (std::size_t j = 0; j < std::size_t(N); ++j)
        if (j != i) c += std::abs(a[j][i]), r += std::abs(a[i][j]);
      if (c == 0 || r == 0) continue;
      const S s = c + r;
      S f = 1, g = r / radix;
      for (; c < g; c *= sq) f *= radix;
      for (g = r * radix; c > g; c /= sq) f /= radix;
      if ((c + r) / f < S(0.95) * s) {
        done = false;
        for (std::size_t j = 0; j < std::size_t(N); ++j) a[i][j] /= f, a[j][i] *= f;
      }
    }
  }
}
// Upper Hessenberg form by eliminations below the subdiagonal, the largest entry as pivot.
template <class S, int N>
void hessenberg(square<S, N>& a) {
  for (std::size_t m = 1; m + 1 < std::size_t(N); ++m) {
    S x = 0;
    std::size_t p = m;
    for (std::size_t j = m; j < std::size_t(N); ++j)
      if (std::abs(a[j][m - 1]) > std::abs(x)) x = a[j][m - 1], p = j;
    if (p != m) {
      for (std::size_t j = m - 1; j < std::size_t(N); ++j) std::swap(a[p][j], a[m][j]);
      for (std::size_t j = 0; j < std::size_t(N); ++j) std::swap(a[j][p], a[j][m]);
    }
    if (x == 0) continue;
    for (std::size_t i = m + 1; i < std::size_t(N); ++i) {
      const S y = a[i][m - 1] / x;
      a[i][m - 1] = 0;
      if (y == 0) continue;
      for (std::size_t j = m; j < std::size_t(N); ++j) a[i][j] -= y * a[m][j];
      for (std::size_t j = 0; j < std::size_t(N); ++j) a[j][m] += y * a[j][i];
    }
  }
}
// The eigenvalues of the Hessenberg matrix a (destroyed) into re, im; false without convergence.
template <class S, int N>
bool francis_qr(square<S, N>& a, std::array<S, std::size_t(N)>& re, std::array<S, std::size_t(N)>& im,
                int sweeps) {
  const auto at = [&](int i, int j) -> S& { return a[std::size_t(i)][std::size_t(j)]; };
  const auto sign = [](S x, S y) { return y >= 0 ? std::abs(x) : -std::abs(x); };
  S norm = 0;
  for (int i = 0; i < N; ++i)
    for (int j = i > 0 ? i - 1 : 0; j < N; ++j) norm += std::abs(at(i, j));
  S t = 0;  // the exceptional shifts so far
  for (int nn = N - 1; nn >= 0;) {
    int its = 0, l;
    do {
      for (l = nn; l >= 1; --l) {  // a negligible subdiagonal entry splits the matrix
        S s = std::abs(at(l - 1, l - 1)) + std::abs(at(l, l));
        if (s == 0) s = norm;
        if (std::abs(at(l, l - 1)) + s == s) {
          at(l, l - 1) = 0;
          break;
        }
      }
      S x = at(nn, nn);
      if (l == nn) {  // one real root
        re[std::size_t(nn)] = x + t, im[std::size_t(nn)] = 0, --nn;
        continue;
      }
      S y = at(nn - 1, nn - 1), w = at(nn, nn - 1) * at(nn - 1, nn);
      if (l == nn - 1) {  // a 2 x 2 block: two real roots or a conjugate pair
        const S p = S(0.5) * (y - x), q = p * p + w, z = std::sqrt(std::abs(q));
        x += t;
        const auto i = std::size_t(nn);
        if (q >= 0) {
          const S zz = p + sign(z, p);
          re[i - 1] = re[i] = x + zz;
          if (zz != 0) re[i] = x - w / zz;
          im[i - 1] = im[i] = 0;
        } else {
          re[i - 1] = re[i] = x + p;
          im[i - 1] = -z, im[i] = z;
        }
        nn -= 2;
        continue;
      }
      if (its == sweeps) return false;
      if (its == 10 || its == 20) {  // exceptional shift
        t += x;
        for (int i = 0; i <= nn; ++i) at(i, i) -= x;
        const S s = std::abs(at(nn, nn - 1)) + std::abs(at(nn - 1, nn - 2));
        y = x = S(0.75) * s;
        w = S(-0.4375) * s * s;
      }
      ++its;
      int m;
      S p = 0, q = 0, r = 0, z = 0;
      for (m = nn - 2; m >= l; --m) {  // two small subdiagonal entries in a row: start there
        z = at(m, m);
        r = x - z;
        S s = y - z;
        p = (r * s - w) / at(m + 1, m) + at(m, m + 1);
        q = at(m + 1, m + 1) - z - r - s;
        r = at(m + 2, m + 1);
        s = std::abs(p) + std::abs(q) + std::abs(r);
        p /= s, q /= s, r /= s;
        if (m == l) break;
        const S u = std::abs(at(m, m - 1)) * (std::abs(q) + std::abs(r)),
                v = std::abs(p) * (std::abs(at(m - 1, m - 1)) + std::abs(z) + std::abs(at(m + 1, m + 1)));
        if (u + v == v) break;
      }
      for (int i = m + 2; i <= nn; ++i) {
        at(i, i - 2) = 0;
        if (i != m + 2) at(i, i - 3) = 0;
      }
      for (int k = m; k <= nn - 1; ++k) {  // the double-shift step by Householder reflections
        if (k != m) {
          p = at(k, k - 1), q = at(k + 1, k - 1), r = k != nn - 1 ? at(k + 2, k - 1) : S(0);
          if ((x = std::abs(p) + std::abs(q) + std::abs(r)) != 0) p /= x, q /= x, r /= x;
        }
        const S s = sign(std::sqrt(p * p + q * q + r * r), p);
        if (s == 0) continue;
        if (k == m) {
          if (l != m) at(k, k - 1) = -at(k, k - 1);
        } else
          at(k, k - 1) = -s * x;
        p += s;
        x = p / s, y = q / s, z = r / s, q /= p, r /= p;
        for (int j = k; j <= nn; ++j) {
          p = at(k, j) + q * at(k + 1, j);
          if (k != nn - 1) p += r * at(k + 2, j), at(k + 2, j) -= p * z;
          at(k + 1, j) -= p * y, at(k, j) -= p * x;
        }
        for (int i = l; i <= (nn < k + 3 ? nn : k + 3); ++i) {
          p = x * at(i, k) + y * at(i, k + 1);
          if (k != nn - 1) p += z * at(i, k + 2), at(i, k + 2) -= p * r;
          at(i, k + 1) -= p * q, at(i, k) -= p;
        }
      }
    } while (l < nn - 1);
  }
  return true;
}
}  // namespace detail

template <class Derived>
spectrum<typename Derived::Scalar, Derived::RowsAtCompileTime> eigenvalues(
    const Eigen::MatrixBase<Derived>& m, int sweeps = 30) {
  static_assert(Derived::RowsAtCompileTime > 0 && Derived::RowsAtCompileTime == Derived::ColsAtCompileTime &&
                    std::is_floating_point_v<typename Derived::Scalar>,
                "kane: eigenvalues takes a square matrix of real numbers of fixed size: copy it into an "
                "Eigen::Matrix<double, N, N>");
  using S = typename Derived::Scalar;
  constexpr int n = Derived::RowsAtCompileTime;
  spectrum<S, n> out;
  detail::square<S, n> a;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a[std::size_t(i)][std::size_t(j)] = m(i, j);
  std::array<S, std::size_t(n)> re{}, im{};
  out.status = solve_status::not_finite;
  if (detail::all_finite_matrix(m)) {
    detail::balance<S, n>(a);
    detail::hessenberg<S, n>(a);
    out.status = detail::francis_qr<S, n>(a, re, im, sweeps) ? solve_status::ok : solve_status::not_converged;
  }
  for (std::size_t i = 0; i < std::size_t(n) && out.status == solve_status::ok; ++i)
    if (!std::isfinite(re[i]) || !std::isfinite(im[i])) out.status = solve_status::not_converged;
  if (out.status != solve_status::ok) {
    out.values.setConstant(
        std::complex<S>(std::numeric_limits<S>::quiet_NaN(), std::numeric_limits<S>::quiet_NaN()));
    return out;
  }
  for (std::size_t i = 1; i < std::size_t(n); ++i)  // by real part, then imaginary part
    for (std::size_t j = i; j > 0 && (re[j] < re[j - 1] || (re[j] == re[j - 1] && im[j] < im[j - 1])); --j)
      std::swap(re[j], re[j - 1]), std::swap(im[j], im[j - 1]);
  for (int i = 0; i < n; ++i) out.values(i) = {re[std::size_t(i)], im[std::size_t(i)]};
  return out;
}

}  // namespace kane
#pragma GCC diagnostic pop
