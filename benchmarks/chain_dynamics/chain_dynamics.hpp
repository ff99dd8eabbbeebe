// Forward dynamics of an n-link spatial chain (n <= 48): joint i's axis cycles
// z, y, x, z, ... about the previous body's axis; joint i+1 at L_i along b_i x;
// link i has mass m_i at its middle (L_i / 2 along b_i x) and a full,
// non-diagonal inertia about that point in B_i; gravity -9.81 n3. Every
// implementation returns q'' without joint torques. Link i's data at index i - 1.
#pragma once

#include <array>
#include <cstddef>

namespace chain_dynamics {
inline constexpr std::size_t max_n = 48;
inline constexpr double g = 9.81;

// link i = 1, 2, ...
constexpr double length_of(std::size_t i) { return 0.1 + 0.05 * double((i * 7) % 5); }
constexpr double mass_of(std::size_t i) { return 0.4 + 0.2 * double((i * 3) % 7); }
// I11, I22, I33, I12, I23, I31 about the mass centre, in B_i
constexpr std::array<double, 6> inertia_of(std::size_t i) {
  const double m = mass_of(i);
  return {m * (0.006 + 0.001 * double(i % 3)),       m * (0.008 + 0.001 * double((i * 5) % 4)),
          m * (0.009 + 0.001 * double((i * 2) % 5)), m * 0.0005 * (double(i % 5) - 2),
          m * 0.0004 * (double((i * 3) % 5) - 2),    m * 0.0003 * (double((i * 4) % 5) - 2)};
}

template <class T, class F>
constexpr std::array<T, max_n> table(F f) {
  std::array<T, max_n> t{};
  for (std::size_t i = 0; i < max_n; ++i) t[i] = f(i + 1);
  return t;
}
inline constexpr auto L = table<double>(length_of);
inline constexpr auto mass = table<double>(mass_of);
inline constexpr auto inertia = table<std::array<double, 6>>(inertia_of);

// positive definite (Sylvester), the moments obeying the triangle inequality
constexpr bool physical(const std::array<double, 6>& j) {
  const double a = j[0], b = j[1], c = j[2], ab = j[3], bc = j[4], ca = j[5];
  const double det = a * (b * c - bc * bc) - ab * (ab * c - bc * ca) + ca * (ab * bc - b * ca);
  return a > 0 && a * b - ab * ab > 0 && det > 0 && a + b > c && b + c > a && c + a > b;
}
constexpr bool all_physical() {
  for (const auto& j : inertia)
    if (!physical(j)) return false;
  return true;
}
static_assert(all_physical());

struct input {
  std::array<double, max_n> q, qd, qdd;  // q'' for inverse dynamics
};
struct output {
  double qdd[max_n];
};
// q'' and its derivatives by q and q' (column-major N x N) of the first N links
struct derivatives {
  double ud[max_n];
  double dq[max_n * max_n], du[max_n * max_n];
};
// q'' of the first N links, the first N entries of q, q'
template <std::size_t N>
void kane_forward(const input&, output&);  // one translation unit per N
// tau = M q'' - f and its derivatives by q and q' (column-major N x N) of the first N links
struct torques {
  double tau[max_n];
};
struct inverse_derivatives {
  double tau[max_n];
  double dq[max_n * max_n], du[max_n * max_n];
};
template <std::size_t N>
void kane_derivatives(const input&, derivatives&);  // analytical, one translation unit per N
template <std::size_t N>
void kane_inverse(const input&, torques&);  // in kane_forward's unit
template <std::size_t N>
void kane_inverse_derivatives(const input&, inverse_derivatives&);  // in kane_derivatives' unit
template <std::size_t N>
void kdl_forward(const input&, output&);  // N = 6, 12, 24, 48
template <std::size_t N>
void hand_forward(const input&, output&);  // N = 6, 12, 24, 48
}  // namespace chain_dynamics
