// Forward-mode dual numbers v + d eps (eps^2 = 0): derivatives of opaque user
// functions at evaluation.
#pragma once

#include <cmath>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S>
struct dual {
  S v{}, d{};
  constexpr dual(S value = S(), S derivative = S()) : v(value), d(derivative) {}
  friend constexpr dual operator+(dual a, dual b) { return {a.v + b.v, a.d + b.d}; }
  friend constexpr dual operator-(dual a, dual b) { return {a.v - b.v, a.d - b.d}; }
  friend constexpr dual operator-(dual a) { return {-a.v, -a.d}; }
  friend constexpr dual operator*(dual a, dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
  friend constexpr dual operator/(dual a, dual b) {
    return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
  }
  friend constexpr dual operator+(dual a, S b) { return {a.v + b, a.d}; }
  friend constexpr dual operator+(S a, dual b) { return {a + b.v, b.d}; }
  friend constexpr dual operator-(dual a, S b) { return {a.v - b, a.d}; }
  friend constexpr dual operator-(S a, dual b) { return {a - b.v, -b.d}; }
  friend constexpr dual operator*(dual a, S b) { return {a.v * b, a.d * b}; }
  friend constexpr dual operator*(S a, dual b) { return {a * b.v, a * b.d}; }
  friend constexpr dual operator/(dual a, S b) { return {a.v / b, a.d / b}; }
  friend constexpr dual operator/(S a, dual b) { return {a / b.v, -a * b.d / (b.v * b.v)}; }
  friend dual sin(dual a) {
    using std::cos, std::sin;
    return {sin(a.v), cos(a.v) * a.d};
  }
  friend dual cos(dual a) {
    using std::cos, std::sin;
    return {cos(a.v), -sin(a.v) * a.d};
  }
  friend dual tan(dual a) {
    using std::cos, std::tan;
    const S c = cos(a.v);
    return {tan(a.v), a.d / (c * c)};
  }
  friend dual exp(dual a) {
    using std::exp;
    const S e = exp(a.v);
    return {e, e * a.d};
  }
  friend dual log(dual a) {
    using std::log;
    return {log(a.v), a.d / a.v};
  }
  friend dual sqrt(dual a) {
    using std::sqrt;
    const S r = sqrt(a.v);
    return {r, a.d / (S(2) * r)};
  }
  friend dual atan(dual a) {
    using std::atan;
    return {atan(a.v), a.d / (S(1) + a.v * a.v)};
  }
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
