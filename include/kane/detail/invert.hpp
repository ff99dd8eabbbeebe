// The inverse of a small fixed-size matrix by LU elimination with full
// pivoting. Rank as Eigen's FullPivLU decides it: a pivot counts if it
// exceeds eps * n times the largest pivot (the first), or a given threshold.
// A 2 x 2 matrix is inverted in closed form under the same rule. The solves of a
// coupled block and of a positive definite system that jets overload.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/packet.hpp"
#include "kane/detail/wide_stores.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// y = U^-1 L^-1 y, a holding L (unit diagonal) below its diagonal and U above, r the 1 / u_kk
template <class S, std::size_t N>
KANE_ALWAYS_INLINE void lu_substitute(const S (&a)[N][N], const S (&r)[N], S (&y)[N]) {
  for (std::size_t i = 0; i < N; ++i) {
    S t = y[i];
    for (std::size_t j = 0; j < i; ++j) t -= a[i][j] * y[j];
    y[i] = t;
  }
  for (std::size_t i = N; i-- > 0;) {
    S t = y[i];
    for (std::size_t j = i + 1; j < N; ++j) t -= a[i][j] * y[j];
    y[i] = t * r[i];
  }
}
// inv = m^-1 and true, or false if a pivot is not above tol (m finite). tol < 0:
// the relative rule above.
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
  // P m Q = L U with full pivoting (the pivot of step k the largest |entry| left, moved to
  // (k, k)); then m^-1 = Q U^-1 L^-1 P, one column of P at a time.
  constexpr std::size_t n = static_cast<std::size_t>(N);  // array bounds are sizes
  S a[n][n];
  std::size_t p[n], q[n];  // row k of P m Q is row p[k] of m; column k is column q[k]
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = q[i] = i;
    for (std::size_t j = 0; j < n; ++j) a[i][j] = m(Eigen::Index(i), Eigen::Index(j));
  }
  S r[n];  // 1 / u_kk
#pragma GCC unroll 8
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t bi = k, bj = k;
    S best = S(-1);
    for (std::size_t i = k; i < n; ++i)
      for (std::size_t j = k; j < n; ++j)
        if (const S x = abs(a[i][j]); x > best) best = x, bi = i, bj = j;
    if (k == 0 && tol < S(0)) tol = std::numeric_limits<S>::epsilon() * S(N) * best;
    if (!(best > tol)) return false;
    for (std::size_t j = 0; j < n; ++j) std::swap(a[k][j], a[bi][j]);
    for (std::size_t i = 0; i < n; ++i) std::swap(a[i][k], a[i][bj]);
    std::swap(p[k], p[bi]), std::swap(q[k], q[bj]);
    r[k] = S(1) / a[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      const S l = a[i][k] * r[k];
      a[i][k] = l;
      for (std::size_t j = k + 1; j < n; ++j) a[i][j] -= l * a[k][j];
    }
  }
#pragma GCC unroll 8
  for (std::size_t c = 0; c < n; ++c) {  // column c of m^-1: L z = P e_c, U y = z, x = Q y
    S y[n];
    for (std::size_t i = 0; i < n; ++i) y[i] = S(p[i] == c);
    lu_substitute(a, r, y);
    for (std::size_t i = 0; i < n; ++i) inv(Eigen::Index(q[i]), Eigen::Index(c)) = y[i];
  }
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
                                   const Eigen::Matrix<S, N, 1>& rhs) {
  return inv * rhs;
}
// m = L D L^T with every index known at compile time (no loop, no square root): what the
// optimizer knows of m (constants, zeros) it carries through. a_ij = L_ij d_j.
template <class S, int N>
inline typename lane_traits<S>::mask solve_unrolled(const Eigen::Matrix<S, N, N>& m,
                                                    const Eigen::Matrix<S, N, 1>& f,
                                                    Eigen::Matrix<S, N, 1>& x) {
  constexpr std::size_t n = std::size_t(N);
  std::array<S, n * n> a, l;
  std::array<S, n> inv, y;
  auto positive = lane_traits<S>::truth(true);
  static_for<n>([&](auto i) {
    static_for<i>([&](auto j) {
      S s = m(Eigen::Index(i), Eigen::Index(j));
      static_for<j>([&](auto k) { s -= a[i * n + k] * l[j * n + k]; });
      a[i * n + j] = s, l[i * n + j] = s * inv[j];
    });
    S d = m(Eigen::Index(i), Eigen::Index(i));
    static_for<i>([&](auto k) { d -= a[i * n + k] * l[i * n + k]; });
    positive = positive && d > S(0);
    inv[i] = S(1) / d;
  });
  static_for<n>([&](auto i) {  // L y = f
    S s = f(Eigen::Index(i));
    static_for<i>([&](auto k) { s -= l[i * n + k] * y[k]; });
    y[i] = s;
  });
  static_for<n>([&](auto r) {  // L^T x = D^-1 y
    constexpr std::size_t i = n - 1 - r;
    S s = y[i] * inv[i];
    static_for<r>([&](auto t) {
      constexpr std::size_t k = n - 1 - t;
      s -= l[k * n + i] * x(Eigen::Index(k));
    });
    x(Eigen::Index(i)) = s;
  });
  return positive;  // x is solved regardless (numbers, no branch): the caller discards it if false
}
// x = m^-1 f for a symmetric m by Cholesky; false if m is not positive definite. Jets
// overload it (jet.hpp).
template <class S, int N>
typename lane_traits<S>::mask solve_positive_definite(const Eigen::Matrix<S, N, N>& m,
                                                      const Eigen::Matrix<S, N, 1>& f,
                                                      Eigen::Matrix<S, N, 1>& x) {
  auto positive = lane_traits<S>::truth(true);
  if constexpr (N <= 12) {
    return solve_unrolled(m, f, x);
  } else {  // m = L L^T by rows (contiguous dot products; Eigen's blocked path packs panels)
    std::array<S, std::size_t(N) * std::size_t(N)> l;
    std::array<S, std::size_t(N)> inv, y;
    using std::sqrt;
    using row = Eigen::Map<const Eigen::Matrix<S, Eigen::Dynamic, 1>>;  // Eigen's packets for the sums
    for (int i = 0; i < N; ++i) {
      S* li = &l[std::size_t(i * N)];
      for (int j = 0; j <= i; ++j) {
        const S* lj = &l[std::size_t(j * N)];
        const S d = m(i, j) - (j == 0 ? S(0) : row(li, j).dot(row(lj, j)));
        if (i == j) {
          if constexpr (lane_traits<S>::width == 1) {
            if (!(d > S(0))) return false;
          } else
            positive = positive && d > S(0);  // NaN rows in the lanes that fail
          li[i] = sqrt(d), inv[std::size_t(i)] = S(1) / li[i];
        } else
          li[j] = d * inv[std::size_t(j)];
      }
      y[std::size_t(i)] = (f(i) - (i == 0 ? S(0) : row(li, i).dot(row(y.data(), i)))) * inv[std::size_t(i)];
    }
    for (int i = N - 1; i >= 0; --i) {
      S d = y[std::size_t(i)];
      for (int k = i + 1; k < N; ++k) d -= l[std::size_t(k * N + i)] * x(k);
      x(i) = d * inv[std::size_t(i)];
    }
  }
  return positive;
}

// M = L D L^T, L unit lower triangular, by plain loops (for a few speeds, where a blocked solver's
// bookkeeping outweighs its arithmetic), factored once; ok() is false where M is not positive
// definite. No square root: the next column waits on one division. solve_negated sets
// X = -M^-1 X for every column of each X (N rows, fixed columns): the columns of all X lie side by
// side in rows of packets, so one l_ik scales W columns.
template <class S, int N>
class cholesky_factor {
  static constexpr std::size_t n = std::size_t(N), W = packet_width<S>;
  std::array<S, n * n> l{};  // l_ij at i n + j below the diagonal, l_ij d_j at j n + i above it
  std::array<S, n> inv{};    // 1 / d_i
  typename lane_traits<S>::mask positive = lane_traits<S>::truth(true);  // per lane for lanes

 public:
  explicit cholesky_factor(const Eigen::Matrix<S, N, N>& m) {
    const auto entry = [&](std::size_t i, std::size_t j, auto&& sum) KANE_ALWAYS_INLINE_LAMBDA {
      S s = m(Eigen::Index(i), Eigen::Index(j));
      sum([&](std::size_t k) KANE_ALWAYS_INLINE_LAMBDA { s -= l[k * n + i] * l[j * n + k]; });
      if (i != j)
        l[j * n + i] = s, l[i * n + j] = s * inv[j];
      else {
        positive = positive && s > S(0);
        inv[i] = S(1) / s;
      }
    };
    if constexpr (n <= 12)  // unrolled
      static_for_inline<n>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
        static_for_inline<i + 1>([&](auto j) KANE_ALWAYS_INLINE_LAMBDA {
          entry(i, j, [](auto&& f) { static_for_inline<decltype(j)::value>([&](auto k) { f(k); }); });
        });
      });
    else
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j <= i; ++j)
          entry(i, j, [j](auto&& f) {
            for (std::size_t k = 0; k < j; ++k) f(k);
          });
  }
  auto ok() const { return positive; }
  template <class... X>
  void solve_negated(X&... x) const {
    static_assert(((X::RowsAtCompileTime == N && (!X::IsRowMajor || N == 1) &&
                    std::is_base_of_v<Eigen::PlainObjectBase<X>, X>)&&...),
                  "solve_negated: each X a plain matrix of N rows, its columns contiguous (column-major)");
    constexpr std::size_t cols = (std::size_t(X::ColsAtCompileTime) + ... + 0);
    constexpr std::size_t P = (cols + W - 1) / W, R = P * W;  // packets and numbers a row
    std::array<S, n * R> b;                                   // row i: (X_0 row i, X_1 row i, ...)
    std::array<S*, cols> column{};
    std::size_t c0 = 0;
    (
        [&] {
          for (Eigen::Index j = 0; j < x.cols(); ++j) column[c0++] = &x(0, j);
        }(),
        ...);
    for (std::size_t i = 0; i < n; ++i)  // each packet of a row built in a register, stored whole
      static_for_inline<P>([&](auto p) KANE_ALWAYS_INLINE_LAMBDA {
        packet<S, W> row = splat<W>(S(0));
        static_for_inline<W>([&](auto k) KANE_ALWAYS_INLINE_LAMBDA {
          constexpr std::size_t c = std::remove_cvref_t<decltype(p)>::value * W + decltype(k)::value;
          if constexpr (c < cols) row[decltype(k)::value] = column[c][i];
        });
        store_packet<W>(row, &b[i * R + p * W]);
      });
    // L y = b, then L^T w = -D^-1 y (w = -z, with L^T z = D^-1 y), V packets of each row from p0 at
    // a time. Row i waits on the row solved just before it: that product comes last, the others
    // first (above 8 rows in two chains, even and odd k).
    const auto sweep = [&](std::size_t p0, auto v) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t V = decltype(v)::value;
      // row i of y (Back false: rows k < i, l_ik) or of w (Back true: rows k > i, l_ki)
      const auto step = [&]<bool Back>(std::size_t i, std::bool_constant<Back>) KANE_ALWAYS_INLINE_LAMBDA {
        using row = std::array<packet<S, W>, V>;
        const auto at = [&](std::size_t k, auto g)
                            KANE_ALWAYS_INLINE_LAMBDA -> S* { return &b[k * R + (p0 + g) * W]; };
        const auto add = [&](row& acc, std::size_t k) KANE_ALWAYS_INLINE_LAMBDA {
          const S a = Back ? l[k * n + i] : l[i * n + k];
          static_for_inline<V>([&](auto g) { acc[g] -= a * load_packet<W>(at(k, g)); });
        };
        constexpr bool two = n > 8;  // chains
        row even;
        [[maybe_unused]] row odd;
        static_for_inline<V>([&](auto g) KANE_ALWAYS_INLINE_LAMBDA {
          even[g] = load_packet<W>(at(i, g));
          if constexpr (Back) even[g] = -inv[i] * even[g];
          if constexpr (two) odd[g] = splat<W>(S(0));
        });
        const std::size_t lo = Back ? i + 1 : 0, hi = Back ? n : i;
        if (lo < hi) {
          const std::size_t last = Back ? lo : hi - 1, end = Back ? hi : hi - 1;
          std::size_t k = Back ? lo + 1 : lo;
          if constexpr (two)
            for (; k + 1 < end; k += 2) add(even, k), add(odd, k + 1);
          for (; k < end; ++k) add(even, k);
          if constexpr (two) static_for_inline<V>([&](auto g) { even[g] += odd[g]; });
          add(even, last);
        }
        static_for_inline<V>([&](auto g) { store_packet<W>(even[g], at(i, g)); });
      };
      for (std::size_t i = 0; i < n; ++i) step(i, std::false_type{});
      for (std::size_t i = n; i-- > 0;) step(i, std::true_type{});
    };
    constexpr std::size_t most = 8;  // packets a sweep
    for (std::size_t p0 = 0; p0 + most <= P; p0 += most) sweep(p0, index_c<most>{});
    if constexpr (P % most != 0) sweep(P - P % most, index_c<P % most>{});
    for (std::size_t c = 0; c < cols; ++c)  // each column stored in blocks
      store_in_blocks<n>(column[c], [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { return b[i * R + c]; });
  }
};
}  // namespace kane::detail
#pragma GCC diagnostic pop
