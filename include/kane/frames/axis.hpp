// Constant unit axes, fixed in both frames of a simple rotation.
//
// direction<X, Y, Z> is the unit vector along (X, Y, Z), components in the
// parent frame (equal to those in the child: the axis is fixed in both).
// The integer direction is normalised at compile time; (0, 0, 0) is rejected.
// A user axis is any type with `static constexpr double components[3]`; it is
// normalised the same way and rejected at compile time if its norm is zero.
#pragma once

#include <array>
#include <concepts>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

constexpr double sqrt_newton(double x) {
  if (!(x > 0.0)) return 0.0;
  double r = x < 1.0 ? 1.0 : x;
  for (int i = 0; i < 200; ++i) {
    double next = 0.5 * (r + x / r);
    if (next == r) break;
    r = next;
  }
  return r;
}

constexpr std::array<double, 3> normalise(double x, double y, double z) {
  double n = sqrt_newton(x * x + y * y + z * z);
  return {x / n, y / n, z / n};
}

}  // namespace detail

// The constant unit axis (X, Y, Z) / |(X, Y, Z)|, fixed in a frame and its parent.
template <int X, int Y, int Z>
struct direction {
  // (X, Y, Z) as given, not normalised
  static constexpr double components[3] = {double(X), double(Y), double(Z)};
};

// A constant direction: `static constexpr double components[3]`.
template <class T>
concept Axis = requires {
  { T::components[0] } -> std::convertible_to<double>;
  requires sizeof(T::components) == 3 * sizeof(T::components[0]);
};

namespace axis {
using x = direction<1, 0, 0>;
using y = direction<0, 1, 0>;
using z = direction<0, 0, 1>;
}  // namespace axis

namespace detail {

// The unit vector of an axis, or index 0/1/2 when it is a coordinate axis.
template <Axis T>
struct unit_axis {
  static constexpr std::array<double, 3> raw = {double(T::components[0]), double(T::components[1]),
                                                double(T::components[2])};
  static_assert(raw[0] * raw[0] + raw[1] * raw[1] + raw[2] * raw[2] > 0.0,
                "kane: an axis direction must not be the zero vector");
  static constexpr std::array<double, 3> value = normalise(raw[0], raw[1], raw[2]);
  // 0, 1, 2 for the frame's own x, y, z (after normalisation); -1 otherwise.
  static constexpr int principal = value[0] == 1.0 && value[1] == 0.0 && value[2] == 0.0   ? 0
                                   : value[0] == 0.0 && value[1] == 1.0 && value[2] == 0.0 ? 1
                                   : value[0] == 0.0 && value[1] == 0.0 && value[2] == 1.0 ? 2
                                                                                           : -1;
};

}  // namespace detail
}  // namespace kane
#pragma GCC diagnostic pop
