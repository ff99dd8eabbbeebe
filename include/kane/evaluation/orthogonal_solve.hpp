// The inverse of a matrix whose blocks have orthogonal rows (the kinematic equations of Euler
// parameters beside u = q'): M_B^-1 = M_B^T (M_B M_B^T)^-1, row by row, no factorization.
#pragma once

#include <array>
#include <cstddef>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/structure.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/status.hpp"

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
// The numbers of X = M^-1 for an orthogonal_form; singular for a zero row, not_finite for NaN
// or inf. The zeros and ones of X are not written. A row r with Inverse[r] != 0 is known to
// have 1 / |row|^2 = Inverse[r] (+-c q_i over Euler parameters of unit norm).
template <class Sys, auto Inverse = std::array<double, Sys::n>{}, class S>
KANE_ALWAYS_INLINE solve_status solve_orthogonal(const table<S, Sys::n, Sys::n>& m,
                                                 table<S, Sys::n, Sys::n>& x) {
  S residue = S(0);  // NaN or inf in a row, or a row norm that overflows
  bool singular = false;
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
  return !(residue == S(0)) && !singular ? solve_status::not_finite
         : singular                      ? solve_status::singular
                                         : solve_status::ok;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
