// Jets: numbers v + sum_i d_i eps_i with eps_i eps_j = 0, the scalar of exact
// first derivatives (forward mode). An evaluator over kane::jet<double, N>
// carries, beside every number it computes, its derivatives along N chosen
// directions of the state; derivatives are exact up to rounding, not differences.
//
// Comparisons read the value v alone, except == and != which compare all parts
// (an "exact zero" skipped by a solver must have zero derivatives too).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/frames/scalar.hpp"

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

template <std::floating_point S, std::size_t N>
struct jet {
  // The derivatives are worked in chunks of one vector register (a vector type of GCC
  // and Clang), N rounded up to whole chunks: d[N], ... is padding, never read.
  static constexpr std::size_t width = detail::simd_bytes > sizeof(S) ? detail::simd_bytes / sizeof(S) : 1,
                               lanes = (N + width - 1) / width * width;
  typedef S chunk __attribute__((vector_size(sizeof(S) * width), aligned(alignof(S))));
  S v;
  std::array<S, lanes> d;

  constexpr jet() : v(), d() {}
  template <class T>
  requires std::is_arithmetic_v<T>
  constexpr jet(T value) : v(S(value)), d() {}  // NOLINT: numbers convert as constants
  struct raw {};
  constexpr explicit jet(raw) {}  // NOLINT: every part written before it is read
  // x_i: the value x seeded in direction i.
  static constexpr jet variable(S x, std::size_t i) {
    jet r(x);
    r.d[i] = S(1);
    return r;
  }

  // f(part) for the parts of the result: a whole chunk at run time (unrolled), one
  // lane in a constant expression; get(a, part) reads a's derivatives there.
  struct lane {
    std::size_t i;
  };
  struct block {
    std::size_t k;
  };
  static constexpr S get(const jet& a, lane p) { return a.d[p.i]; }
  static chunk get(const jet& a, block p) {
    chunk x;
    std::memcpy(&x, &a.d[p.k], sizeof x);
    return x;
  }
  template <class F>
  static constexpr jet make(S value, F f) {
    jet r{raw{}};
    r.v = value;
    if (std::is_constant_evaluated()) {
      for (std::size_t i = 0; i < lanes; ++i) r.d[i] = f(lane{i});
    } else {
#pragma GCC unroll 16
      for (std::size_t k = 0; k < lanes; k += width) {
        const chunk x = f(block{k});
        std::memcpy(&r.d[k], &x, sizeof x);
      }
    }
    return r;
  }
  friend constexpr jet operator+(const jet& a, const jet& b) {
    return make(a.v + b.v, [&](auto p) { return get(a, p) + get(b, p); });
  }
  friend constexpr jet operator-(const jet& a, const jet& b) {
    return make(a.v - b.v, [&](auto p) { return get(a, p) - get(b, p); });
  }
  friend constexpr jet operator*(const jet& a, const jet& b) {
    return make(a.v * b.v, [&](auto p) { return get(a, p) * b.v + a.v * get(b, p); });
  }
  friend constexpr jet operator/(const jet& a, const jet& b) {
    const S r = S(1) / b.v, q = a.v * r;
    return make(q, [&](auto p) { return (get(a, p) - q * get(b, p)) * r; });
  }
  friend constexpr jet operator+(const jet& a) { return a; }
  friend constexpr jet operator-(const jet& a) {
    return make(-a.v, [&](auto p) { return -get(a, p); });
  }
  constexpr jet& operator+=(const jet& b) { return *this = *this + b; }
  constexpr jet& operator-=(const jet& b) { return *this = *this - b; }
  constexpr jet& operator*=(const jet& b) { return *this = *this * b; }
  constexpr jet& operator/=(const jet& b) { return *this = *this / b; }

  friend constexpr bool operator==(const jet& a, const jet& b) {
    bool same = a.v == b.v;
    for (std::size_t i = 0; i < N; ++i) same = same && a.d[i] == b.d[i];
    return same;
  }
  friend constexpr bool operator<(const jet& a, const jet& b) { return a.v < b.v; }
  friend constexpr bool operator>(const jet& a, const jet& b) { return a.v > b.v; }
  friend constexpr bool operator<=(const jet& a, const jet& b) { return a.v <= b.v; }
  friend constexpr bool operator>=(const jet& a, const jet& b) { return a.v >= b.v; }

  // f(v) + f'(v) d
  friend constexpr jet chain(const jet& a, S f, S df) {
    return make(f, [&](auto p) { return df * get(a, p); });
  }
  friend jet sin(const jet& a) { return chain(a, std::sin(a.v), std::cos(a.v)); }
  friend jet cos(const jet& a) { return chain(a, std::cos(a.v), -std::sin(a.v)); }
  friend jet tan(const jet& a) {
    const S c = std::cos(a.v);
    return chain(a, std::tan(a.v), S(1) / (c * c));
  }
  friend jet sqrt(const jet& a) {
    const S r = std::sqrt(a.v);
    return chain(a, r, S(1) / (S(2) * r));
  }
  friend jet exp(const jet& a) {
    const S e = std::exp(a.v);
    return chain(a, e, e);
  }
  friend jet log(const jet& a) { return chain(a, std::log(a.v), S(1) / a.v); }
  friend jet atan(const jet& a) { return chain(a, std::atan(a.v), S(1) / (S(1) + a.v * a.v)); }
  friend jet atan2(const jet& y, const jet& x) {
    const S r = S(1) / (x.v * x.v + y.v * y.v);
    return make(std::atan2(y.v, x.v), [&](auto p) { return (x.v * get(y, p) - y.v * get(x, p)) * r; });
  }
  friend jet abs(const jet& a) { return a.v < S(0) ? -a : a; }
  friend jet ldexp(jet a, int e) {
    a.v = std::ldexp(a.v, e);
    for (std::size_t i = 0; i < N; ++i) a.d[i] = std::ldexp(a.d[i], e);
    return a;
  }
  friend jet frexp(const jet& a, int* e) { return ldexp(a, -(std::frexp(a.v, e), *e)); }
  friend bool isfinite(const jet& a) {
    bool f = std::isfinite(a.v);
    for (std::size_t i = 0; i < N; ++i) f = f && std::isfinite(a.d[i]);
    return f;
  }
};

template <class S, std::size_t N>
struct is_scalar<jet<S, N>> : std::true_type {};

}  // namespace kane

template <class S, std::size_t N>
class std::numeric_limits<kane::jet<S, N>> : public std::numeric_limits<S> {
 public:
  static constexpr kane::jet<S, N> epsilon() noexcept { return std::numeric_limits<S>::epsilon(); }
  static constexpr kane::jet<S, N> quiet_NaN() noexcept { return std::numeric_limits<S>::quiet_NaN(); }
  static constexpr kane::jet<S, N> infinity() noexcept { return std::numeric_limits<S>::infinity(); }
  static constexpr kane::jet<S, N> max() noexcept { return std::numeric_limits<S>::max(); }
  static constexpr kane::jet<S, N> min() noexcept { return std::numeric_limits<S>::min(); }
  static constexpr kane::jet<S, N> lowest() noexcept { return std::numeric_limits<S>::lowest(); }
};

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
