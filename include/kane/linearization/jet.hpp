// Jets: numbers v + sum_i d_i eps_i with eps_i eps_j = 0, the scalar of exact first derivatives (forward
// mode). An evaluator over kane::jet<double, N> carries, beside every number it computes, its derivatives
// along N chosen directions of the state; derivatives are exact up to rounding, not differences.
//
// Comparisons read the value v alone, except == and != which compare all parts (an "exact zero" skipped
// by a solver must have zero derivatives too).
#pragma once

#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/invert.hpp"
#include "kane/scalars/scalar.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// Bytes of the widest vector register of the target (GCC and Clang predefine these).
#if defined(__AVX512F__)
inline constexpr std::size_t simd_bytes = 64;
#elif defined(__AVX__)
inline constexpr std::size_t simd_bytes = 32;
#elif defined(__SSE2__) || defined(__ARM_NEON)
inline constexpr std::size_t simd_bytes = 16;
#else
inline constexpr std::size_t simd_bytes = 0;
#endif
}  // namespace detail

// The jet (value, e_k for every chunk k) as straight-line code: no call or callback per
// operation, which would cost the compiler a function to inline at every use.
#define KANE_JET_OF(value, e_k)                                                       \
  jet out;                                                                            \
  out.v = (value);                                                                    \
  _Pragma("GCC unroll 16") for (std::size_t k = 0; k < chunks; ++k) out.c[k] = (e_k); \
  return out

// v + sum d_i eps_i: a number with its first derivatives along N directions (forward mode).
template <std::floating_point S, std::size_t N>
struct jet {
  // The derivatives come in chunks of one vector register, width numbers each, N rounded up to whole chunks.
  // The chunk follows the target (-mavx...): units built for different targets must not exchange jets.
  static constexpr std::size_t width = detail::simd_bytes > sizeof(S) ? detail::simd_bytes / sizeof(S) : 1,
                               chunks = (N + width - 1) / width;
  // A vector type of GCC and Clang: arithmetic works chunk by chunk, so no jet is a constant expression
  // (Clang does not evaluate vector types there). Chunks keep their natural alignment (their size), so
  // none straddles a cache line (8-byte alignment made the bicycle's A slower).
  typedef S chunk __attribute__((vector_size(sizeof(S) * width)));
  // the value v
  S v;
  // d_0 .. d_N-1 in chunks; part(i) reads d_i
  chunk c[chunks];

  jet() = default;  // like a double: jet x; is uninitialised, jet x{}; is zero
  // a number as a constant: zero derivatives
  template <class T>
  requires std::is_arithmetic_v<T> jet(T value) : v(S(value)), c() {}  // NOLINT: numbers convert as constants
  // x_i: the value x seeded in direction i.
  static jet variable(S x, std::size_t i) {
    jet r(x);
    r.c[i / width][i % width] = S(1);
    return r;
  }
  // d_i
  S part(std::size_t i) const { return c[i / width][i % width]; }

  // a + b
  friend jet operator+(const jet& a, const jet& b) { KANE_JET_OF(a.v + b.v, a.c[k] + b.c[k]); }
  // a - b
  friend jet operator-(const jet& a, const jet& b) { KANE_JET_OF(a.v - b.v, a.c[k] - b.c[k]); }
  // a b, by the product rule
  friend jet operator*(const jet& a, const jet& b) { KANE_JET_OF(a.v * b.v, a.c[k] * b.v + a.v * b.c[k]); }
  // by a number: its derivatives are zero
  friend jet operator*(const jet& a, S b) { KANE_JET_OF(a.v * b, a.c[k] * b); }
  // a b = b a
  friend jet operator*(S a, const jet& b) { return b * a; }
  // a / b, by the quotient rule
  friend jet operator/(const jet& a, const jet& b) {
    const S r = S(1) / b.v, q = a.v * r;
    KANE_JET_OF(q, (a.c[k] - q * b.c[k]) * r);
  }
  // +a = a
  friend jet operator+(const jet& a) { return a; }
  // -a
  friend jet operator-(const jet& a) { KANE_JET_OF(-a.v, -a.c[k]); }
  // a = a + b
  jet& operator+=(const jet& b) { return *this = *this + b; }
  // a = a - b
  jet& operator-=(const jet& b) { return *this = *this - b; }
  // a = a b
  jet& operator*=(const jet& b) { return *this = *this * b; }
  // a = a / b
  jet& operator/=(const jet& b) { return *this = *this / b; }

  // v and every d_i equal
  friend bool operator==(const jet& a, const jet& b) {
    bool same = a.v == b.v;
    for (std::size_t i = 0; i < N; ++i) same = same && a.part(i) == b.part(i);
    return same;
  }
  // a.v < b.v
  friend bool operator<(const jet& a, const jet& b) { return a.v < b.v; }
  // a.v > b.v
  friend bool operator>(const jet& a, const jet& b) { return a.v > b.v; }
  // a.v <= b.v
  friend bool operator<=(const jet& a, const jet& b) { return a.v <= b.v; }
  // a.v >= b.v
  friend bool operator>=(const jet& a, const jet& b) { return a.v >= b.v; }

  // f(v) + f'(v) d
  friend jet chain(const jet& a, S f, S df) { KANE_JET_OF(f, df * a.c[k]); }
  // sin v + d cos v
  friend jet sin(const jet& a) { return chain(a, std::sin(a.v), std::cos(a.v)); }
  // cos v - d sin v
  friend jet cos(const jet& a) { return chain(a, std::cos(a.v), -std::sin(a.v)); }
  // tan v + d / cos^2 v
  friend jet tan(const jet& a) {
    const S cos_v = std::cos(a.v);
    return chain(a, std::tan(a.v), S(1) / (cos_v * cos_v));
  }
  // sqrt v + d / (2 sqrt v)
  friend jet sqrt(const jet& a) {
    const S r = std::sqrt(a.v);
    return chain(a, r, S(1) / (S(2) * r));
  }
  // exp v + d exp v
  friend jet exp(const jet& a) {
    const S e = std::exp(a.v);
    return chain(a, e, e);
  }
  // log v + d / v
  friend jet log(const jet& a) { return chain(a, std::log(a.v), S(1) / a.v); }
  // atan v + d / (1 + v^2)
  friend jet atan(const jet& a) { return chain(a, std::atan(a.v), S(1) / (S(1) + a.v * a.v)); }
  // atan2(y.v, x.v) + (x.v y.d - y.v x.d) / (x.v^2 + y.v^2)
  friend jet atan2(const jet& y, const jet& x) {
    const S r = S(1) / (x.v * x.v + y.v * y.v);
    KANE_JET_OF(std::atan2(y.v, x.v), (x.v * y.c[k] - y.v * x.c[k]) * r);
  }
  // |a|: -a for v < 0, else a
  friend jet abs(const jet& a) { return a.v < S(0) ? -a : a; }
  // a 2^e: every part scaled
  friend jet ldexp(jet a, int e) {
    a.v = std::ldexp(a.v, e);
    for (std::size_t i = 0; i < N; ++i) a.c[i / width][i % width] = std::ldexp(a.part(i), e);
    return a;
  }
  // a 2^-e, with e as std::frexp sets it for v
  friend jet frexp(const jet& a, int* e) { return ldexp(a, -(std::frexp(a.v, e), *e)); }
  // v and every d_i finite
  friend bool isfinite(const jet& a) {
    bool f = std::isfinite(a.v);
    for (std::size_t i = 0; i < N; ++i) f = f && std::isfinite(a.part(i));
    return f;
  }
};
#undef KANE_JET_OF

// A coupled block B of a structured solve on jets: X, the inverse of its values alone.
template <class S, std::size_t D, int N>
bool factor_block(const Eigen::Matrix<jet<S, D>, N, N>& b, Eigen::Matrix<jet<S, D>, N, N>& inv,
                  jet<S, D> tol) {
  Eigen::Matrix<S, N, N> v, x;
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) v(i, j) = b(i, j).v;
  if (!detail::invert(v, x, tol.v)) return false;
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) inv(i, j) = jet<S, D>(x(i, j));
  return true;
}
// y = X t and dy = X (dt - dB y) for the block B and X of factor_block, one chunk at a time.
template <class S, std::size_t D, int N>
Eigen::Matrix<jet<S, D>, N, 1> solve_block(const Eigen::Matrix<jet<S, D>, N, N>& inv,
                                           const Eigen::Matrix<jet<S, D>, N, N>& b,
                                           const Eigen::Matrix<jet<S, D>, N, 1>& rhs) {
  using J = jet<S, D>;
  using I = Eigen::Index;
  constexpr std::size_t n = std::size_t(N), chunks = J::chunks;
  S y[n] = {};
  typename J::chunk r[n][chunks];
  for (std::size_t i = 0; i < n; ++i)
#pragma GCC unroll 8
    for (std::size_t k = 0; k < n; ++k) y[i] += inv(I(i), I(k)).v * rhs(I(k)).v;
  for (std::size_t i = 0; i < n; ++i)
#pragma GCC unroll 16
    for (std::size_t q = 0; q < chunks; ++q) {
      r[i][q] = rhs(I(i)).c[q];
#pragma GCC unroll 8
      for (std::size_t k = 0; k < n; ++k) r[i][q] -= b(I(i), I(k)).c[q] * y[k];
    }
  Eigen::Matrix<J, N, 1> out;
  for (std::size_t i = 0; i < n; ++i) {
    out(I(i)).v = y[i];
#pragma GCC unroll 16
    for (std::size_t q = 0; q < chunks; ++q) {
      typename J::chunk d = {};
#pragma GCC unroll 8
      for (std::size_t k = 0; k < n; ++k) d += inv(I(i), I(k)).v * r[k][q];
      out(I(i)).c[q] = d;
    }
  }
  return out;
}
// x = m^-1 f on jets: m's values factored once (L D L^T), then M dx = df - dM x for each direction.
template <class S, std::size_t D, int N>
bool solve_positive_definite(const Eigen::Matrix<jet<S, D>, N, N>& m, const Eigen::Matrix<jet<S, D>, N, 1>& f,
                             Eigen::Matrix<jet<S, D>, N, 1>& x) {
  using I = Eigen::Index;
  Eigen::Matrix<S, N, N> mv;
  Eigen::Matrix<S, N, 1> xv;  // -f, then m^-1 f
  for (I i = 0; i < N; ++i) {
    xv(i) = -f(i).v;
    for (I j = 0; j < N; ++j) mv(i, j) = m(i, j).v;
  }
  const detail::cholesky_factor<S, N> factor(mv);
  if (!factor.ok()) return false;
  factor.solve_negated(xv);
  Eigen::Matrix<S, N, int(D)> r;  // dM x - df, then m^-1 (df - dM x)
  for (I i = 0; i < N; ++i)
    for (std::size_t d = 0; d < D; ++d) {
      S ri = -f(i).part(d);
      for (I k = 0; k < N; ++k) ri += m(i, k).part(d) * xv(k);
      r(i, I(d)) = ri;
    }
  factor.solve_negated(r);
  for (I i = 0; i < N; ++i) {
    x(i) = jet<S, D>(xv(i));
    for (std::size_t d = 0; d < D; ++d) x(i).c[d / jet<S, D>::width][d % jet<S, D>::width] = r(i, I(d));
  }
  return true;
}

template <class S, std::size_t N>
struct is_scalar<jet<S, N>> : std::true_type {};
// S, the real numbers of a jet
template <class S, std::size_t N>
struct real_type<jet<S, N>> {
  // S
  using type = S;
};

}  // namespace kane
#pragma GCC diagnostic pop

// the limits of S as jets (zero derivatives)
template <class S, std::size_t N>
class std::numeric_limits<kane::jet<S, N>> : public std::numeric_limits<S> {
 public:
  static kane::jet<S, N> epsilon() noexcept { return std::numeric_limits<S>::epsilon(); }
  static kane::jet<S, N> quiet_NaN() noexcept { return std::numeric_limits<S>::quiet_NaN(); }
  static kane::jet<S, N> infinity() noexcept { return std::numeric_limits<S>::infinity(); }
  static kane::jet<S, N> max() noexcept { return std::numeric_limits<S>::max(); }
  static kane::jet<S, N> min() noexcept { return std::numeric_limits<S>::min(); }
  static kane::jet<S, N> lowest() noexcept { return std::numeric_limits<S>::lowest(); }
};

// Eigen's traits of S for jets: N + 1 numbers to read and add, 2 N + 1 to multiply
template <class S, std::size_t N>
struct Eigen::NumTraits<kane::jet<S, N>> : Eigen::NumTraits<S> {
  using Real = kane::jet<S, N>;
  using NonInteger = kane::jet<S, N>;
  using Nested = kane::jet<S, N>;
  using Literal = kane::jet<S, N>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = int(N) + 1,
    AddCost = int(N) + 1,
    MulCost = 2 * int(N) + 1
  };
  static inline Real epsilon() { return Eigen::NumTraits<S>::epsilon(); }
  static inline Real dummy_precision() { return Eigen::NumTraits<S>::dummy_precision(); }
  static inline Real highest() { return Eigen::NumTraits<S>::highest(); }
  static inline Real lowest() { return Eigen::NumTraits<S>::lowest(); }
  static inline int digits10() { return Eigen::NumTraits<S>::digits10(); }
};
