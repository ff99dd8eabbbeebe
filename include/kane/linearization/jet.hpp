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
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/frames/scalar.hpp"

namespace kane {

template <std::floating_point S, std::size_t N>
struct jet {
  S v{};
  std::array<S, N> d{};

  constexpr jet() = default;
  template <class T>
  requires std::is_arithmetic_v<T>
  constexpr jet(T value) : v(S(value)) {}  // NOLINT: numbers convert as constants
  // x_i: the value x seeded in direction i.
  static constexpr jet variable(S x, std::size_t i) {
    jet r(x);
    r.d[i] = S(1);
    return r;
  }

  constexpr jet& operator+=(const jet& b) {
    v += b.v;
    for (std::size_t i = 0; i < N; ++i) d[i] += b.d[i];
    return *this;
  }
  constexpr jet& operator-=(const jet& b) {
    v -= b.v;
    for (std::size_t i = 0; i < N; ++i) d[i] -= b.d[i];
    return *this;
  }
  constexpr jet& operator*=(const jet& b) {
    for (std::size_t i = 0; i < N; ++i) d[i] = d[i] * b.v + v * b.d[i];
    v *= b.v;
    return *this;
  }
  constexpr jet& operator/=(const jet& b) {
    const S r = S(1) / b.v;
    v *= r;
    for (std::size_t i = 0; i < N; ++i) d[i] = (d[i] - v * b.d[i]) * r;
    return *this;
  }
  friend constexpr jet operator+(jet a, const jet& b) { return a += b; }
  friend constexpr jet operator-(jet a, const jet& b) { return a -= b; }
  friend constexpr jet operator*(jet a, const jet& b) { return a *= b; }
  friend constexpr jet operator/(jet a, const jet& b) { return a /= b; }
  friend constexpr jet operator+(const jet& a) { return a; }
  friend constexpr jet operator-(jet a) {
    a.v = -a.v;
    for (S& x : a.d) x = -x;
    return a;
  }

  friend constexpr bool operator==(const jet& a, const jet& b) { return a.v == b.v && a.d == b.d; }
  friend constexpr bool operator<(const jet& a, const jet& b) { return a.v < b.v; }
  friend constexpr bool operator>(const jet& a, const jet& b) { return a.v > b.v; }
  friend constexpr bool operator<=(const jet& a, const jet& b) { return a.v <= b.v; }
  friend constexpr bool operator>=(const jet& a, const jet& b) { return a.v >= b.v; }

  // f(v) + f'(v) d
  friend constexpr jet chain(const jet& a, S f, S df) {
    jet r(f);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = df * a.d[i];
    return r;
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
    jet out(std::atan2(y.v, x.v));
    for (std::size_t i = 0; i < N; ++i) out.d[i] = (x.v * y.d[i] - y.v * x.d[i]) * r;
    return out;
  }
  friend jet abs(const jet& a) { return a.v < S(0) ? -a : a; }
  friend jet ldexp(jet a, int e) {
    a.v = std::ldexp(a.v, e);
    for (S& x : a.d) x = std::ldexp(x, e);
    return a;
  }
  friend jet frexp(const jet& a, int* e) { return ldexp(a, -(std::frexp(a.v, e), *e)); }
  friend bool isfinite(const jet& a) {
    bool f = std::isfinite(a.v);
    for (S x : a.d) f = f && std::isfinite(x);
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
