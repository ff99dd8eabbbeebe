// The inverse of a matrix whose blocks have orthogonal rows (the kinematic equations of Euler
// parameters beside u = q'): M_B^-1 = M_B^T (M_B M_B^T)^-1, row by row, no factorization.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/structure.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// Sys's M is block diagonal, each block a 1 or of orthogonal rows (orthogonal_block): then
// X = M^-1 is M_B^T (M_B M_B^T)^-1 row by row, no factorization (the kinematic equations of
// Euler parameters and u = q'). Sys: as solve_structured, with k = n and R the identity.
template <class Sys>
constexpr bool orthogonal_form() {
  bool ok = true;
  for (std::size_t b = 0; ok && b < Sys::form.count; ++b) {
    const std::size_t first = Sys::form.start[b], size = Sys::form.start[b + 1] - first;
    const std::size_t c = Sys::form.order[first];
    ok = size == 1 ? Sys::m[Sys::form.row[c]][c] == entry::one : orthogonal_block<Sys>(b);
  }
  for (std::size_t c = 0; ok && c < Sys::n; ++c)
    for (std::size_t d = 0; d < Sys::n; ++d)
      ok = ok && (Sys::m[Sys::form.row[c]][d] == entry::zero || Sys::form.block[d] == Sys::form.block[c]);
  return ok;
}
// c and i where X is +-c q_i (c > 0 a constant), else c = 0.
struct scaled_coordinate {
  double c = 0;
  std::size_t i = 0;
};
template <class X>
constexpr scaled_coordinate as_scaled_coordinate() {
  if constexpr (coordinate_info<X>::value) {
    if constexpr (X::order == 0) return {1.0, X::index};
    return {};
  } else if constexpr (is_v<X, neg>)
    return as_scaled_coordinate<std::remove_cvref_t<decltype(X::x)>>();
  else if constexpr (is_v<X, mul> && requires { std::remove_cvref_t<decltype(X::l)>::num; }) {
    using L = std::remove_cvref_t<decltype(X::l)>;
    scaled_coordinate r = as_scaled_coordinate<std::remove_cvref_t<decltype(X::r)>>();
    r.c *= double(L::num < 0 ? -L::num : L::num) / double(L::den);
    return r;
  } else
    return {};
}

// The four i are the Euler parameters of a frame of Closure (of unit norm in the evaluator).
template <class... F>
constexpr bool euler_parameters_of(list<F...>, const std::array<std::size_t, 4>& i) {
  const auto of = [&](const auto& c) {
    bool all = true;
    for (std::size_t a : i) all = all && (a == c[0] || a == c[1] || a == c[2] || a == c[3]);
    return all && i[0] != i[1] && i[0] != i[2] && i[0] != i[3] && i[1] != i[2] && i[1] != i[3] &&
           i[2] != i[3];
  };
  return ([&] {
    if constexpr (euler_edge<F>)
      return of(F::step::coordinates);
    else
      return false;
  }() || ...);
}

// 1 / |Y_R|^2 where each number of Y's row R is +-c q_i, one c, over the Euler parameters of a
// frame of Closure; else 0 (Sys: the kde_system of Speeds).
template <class Sys, class Speeds, class Closure, std::size_t R>
constexpr double inverse_norm() {
  std::array<scaled_coordinate, Sys::n> e{};
  bool ok = true;
  static_for<Sys::n>([&](auto c) {
    if constexpr (Sys::m[R][c] == entry::other)
      e[c] = as_scaled_coordinate<
          std::remove_cv_t<decltype(diff(std::get<R>(Speeds::definitions), coordinate<c + 1, 1>{}))>>();
    else if constexpr (Sys::m[R][c] == entry::one)
      ok = false;
  });
  std::array<std::size_t, 4> i{};
  std::size_t n = 0;
  double c = 0;
  for (std::size_t k = 0; k < Sys::n; ++k)
    if (Sys::m[R][k] == entry::other) {
      ok = ok && e[k].c > 0 && n < 4 && (c == 0 || e[k].c == c);
      if (ok) i[n++] = e[k].i, c = e[k].c;
    }
  return ok && n == 4 && euler_parameters_of(Closure{}, i) ? 1 / (c * c) : 0;
}
template <class Sys, class Speeds, class Closure>
constexpr std::array<double, Sys::n> inverse_norms() {
  return []<std::size_t... R>(std::index_sequence<R...>) {
    return std::array<double, Sys::n>{inverse_norm<Sys, Speeds, Closure, R>()...};
  }
  (std::make_index_sequence<Sys::n>{});
}

// The numbers of X = M^-1 for an orthogonal_form; singular for a zero row, not_finite for NaN
// or inf. The zeros and ones of X are not written. A row r with Inverse[r] != 0 is known to
// have 1 / |row|^2 = Inverse[r] (+-c q_i over Euler parameters of unit norm).
template <class Sys, auto Inverse = std::array<double, Sys::n>{}, class S>
KANE_ALWAYS_INLINE status_of<S> solve_orthogonal(const table<S, Sys::n, Sys::n>& m,
                                                 table<S, Sys::n, Sys::n>& x) {
  S residue = -S(0);  // NaN or inf in a row, or a row norm that overflows
  auto singular = lane_traits<S>::truth(false);
  static_for<Sys::form.count>([&](auto b) {
    constexpr std::size_t first = Sys::form.start[b], size = Sys::form.start[b + 1] - first;
    if constexpr (size > 1) {
      static_for<size>([&](auto a) {
        constexpr std::size_t row = Sys::form.row[Sys::form.order[first + a]];
        std::array<S, size> v;
        static_for<size>([&](auto e) {
          constexpr std::size_t c = Sys::form.order[first + e];
          v[e] = Sys::m[row][c] == entry::one ? S(1) : Sys::m[row][c] == entry::zero ? S(0) : m[row][c];
        });
        S k = S(Inverse[row]);
        if constexpr (Inverse[row] == 0) {
          S n2 = S(0);
          static_for<size>([&](auto e) { n2 += v[e] * v[e]; });
          singular = singular || n2 == S(0);
          k = S(1) / n2;
          residue += k - k;
        }
        static_for<size>([&](auto e) {
          constexpr std::size_t c = Sys::form.order[first + e];
          if constexpr (Sys::x[c][row] == entry::other) x[c][row] = v[e] * k;
        });
      });
    }
  });
  return checks<S>(!singular, solve_status::singular, residue == S(0), solve_status::not_finite);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
