// X = M^-1 R for a small M whose zero pattern and block form are known at
// compile time (structure.hpp): substitution block after block, a division
// for a block of one unknown (none for an exact one), an inverse by LU with full pivoting
// only for a coupled block. Zeros and ones of M, R and X are never touched.
//
// Rank rule: a pivot counts if |pivot| > eps * n * max |M_ij|. A block of one
// unknown tests |pivot| / (eps n) > max |M_ij| and divides by its pivot, so
// neither the threshold nor 1/pivot leaves the range of S. A coupled block is
// solved for f M, with f a power of two that brings a max |M_ij| outside about
// [sqrt(min), sqrt(max)] of S into [1/2, 1) (M x = R as f M x = f R, exact).
// M and sM get the same status for every power of two s that keeps the entries
// of sM normal (any other s rounds sM, and the rule holds to that rounding).
// Status ok means every number of X is finite; not_finite if M holds inf, or
// NaN where no finite pivot failed, or if what is produced is not finite (an X
// beyond the range of S, as for M = 1e-310 I); singular if a finite pivot
// fails the rule. X is NaN whenever the status is not ok.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/choices.hpp"
#include "kane/detail/inline.hpp"
#include "kane/detail/invert.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/structure.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/evaluation/power_of_two.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/scalars/scalar.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S, std::size_t R, std::size_t C>
using table = std::array<std::array<S, C>, R>;

// What a solve keeps of M: the rank rule's scale, the power of two f, whether
// a finite pivot failed, and (f M_B)^-1 of each coupled block B in its places.
template <class S, std::size_t N>
struct structured_factors {
  table<S, N, N> inverse;
  S scale;
  // a number (on jets: no derivatives; on lanes one per lane)
  std::conditional_t<lane_traits<S>::width == 1, typename real_type<S>::type, S> f;
  typename lane_traits<S>::mask singular;
};
// A matrix of a known zero pattern and its factors: more right-hand sides later.
template <class S, std::size_t N>
struct factored {
  table<S, N, N> m;
  structured_factors<S, N> factors;
};

// M_ij: 1 where the pattern says so, else the number.
template <class Sys, class S, std::size_t I, std::size_t J>
KANE_ALWAYS_INLINE S entry_value(const table<S, Sys::n, Sys::n>& m, index_c<I>, index_c<J>) {
  if constexpr (Sys::m[I][J] == entry::one)
    return S(1);
  else
    return m[I][J];
}

// f M_B of the coupled block of size unknowns from the place first of the block order (M's zeros
// and ones from the pattern: only its other entries are read).
template <class Sys, std::size_t First, std::size_t Size, class S, class F>
KANE_ALWAYS_INLINE Eigen::Matrix<S, int(Size), int(Size)> scaled_block(const table<S, Sys::n, Sys::n>& m,
                                                                       F f) {
  Eigen::Matrix<S, int(Size), int(Size)> block;
  static_for_inline<Size * Size>([&](auto ab) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t a = ab / Size, e = ab % Size, row = Sys::form.row[Sys::form.order[First + a]],
                          col = Sys::form.order[First + e];
    if constexpr (Sys::m[row][col] == entry::one)
      block(a, e) = S(f);
    else if constexpr (Sys::m[row][col] == entry::zero)  // not stored
      block(a, e) = S(0);
    else
      block(a, e) = m[row][col] * f;
  });
  return block;
}

// Block b of Sys has orthogonal rows (Sys::orthogonal, where given).
template <class Sys>
constexpr bool orthogonal_block(std::size_t b) {
  if constexpr (requires { Sys::orthogonal; })
    return Sys::orthogonal[b];
  else
    return false;
}
// Sys: static constexpr n, m (pattern n x n), form (blocks_of(m)).
template <class Sys, class S>
KANE_ALWAYS_INLINE structured_factors<S, Sys::n> factor_structured(const table<S, Sys::n, Sys::n>& m) {
  static_assert(Sys::form.regular);
  using std::abs;
  using limits = std::numeric_limits<S>;
  constexpr std::size_t n = Sys::n;
  auto value = [&](auto i, auto j) { return entry_value<Sys>(m, i, j); };
  structured_factors<S, n> out{};
  out.singular = lane_traits<S>::truth(false);
  static_for_inline<n * n>([&](auto ij) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t i = ij / n, j = ij % n;
    if constexpr (Sys::m[i][j] != entry::zero) {
      const S a = abs(value(index_c<i>{}, index_c<j>{}));
      out.scale = lane_traits<S>::select(a > out.scale, a, out.scale);
    }
  });
  const S scale = out.scale;
  using real = typename real_type<S>::type;
  out.f = real(1);  // 2^-e with 2^(e-1) <= scale < 2^e, e clamped so that f is normal
  constexpr bool coupled = [] {
    for (std::size_t b = 0; b < Sys::form.count; ++b)
      if (Sys::form.start[b + 1] - Sys::form.start[b] > 1) return true;
    return false;
  }();
  if constexpr (coupled) {
    constexpr real lo = pow2<real>(limits::min_exponent / 2), hi = pow2<real>(limits::max_exponent / 2);
    const auto outside = scale > S(0) && scale <= limits::max() && !(scale >= S(lo) && scale <= S(hi));
    if constexpr (lane_traits<S>::width > 1) {
      if (any_of(outside))  // a branch, rarely taken: the solve does not wait on the scaling
        out.f = lane_traits<S>::select(outside, inverse_power_of_two(scale), out.f);
    } else if (outside)
      out.f = inverse_power_of_two(scale);
  }
  static_for_inline<Sys::form.count>([&](auto b) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t first = Sys::form.start[b], size = Sys::form.start[b + 1] - first;
    if constexpr (size == 1) {
      constexpr std::size_t c = Sys::form.order[first], row = Sys::form.row[c];
      if constexpr (Sys::m[row][c] == entry::other) {
        constexpr real inverse_tol = real(1) / (std::numeric_limits<real>::epsilon() *
                                                real(n > 0 ? n : 1));  // |p| > tol as |p| / (eps n) > scale
        const S pivot = m[row][c];
        out.singular = out.singular || (pivot == pivot && !(abs(pivot) * S(inverse_tol) > scale));
      }
    } else if constexpr (orthogonal_block<Sys>(b)) {  // B^-1 = B^T (B B^T)^-1, B B^T diagonal
      const auto f = out.f;
      const S tol = limits::epsilon() * S(n) * (scale * f);
      const auto block = scaled_block<Sys, first, size>(m, f);
      Eigen::Matrix<S, int(size), int(size)> inverse;
      static_for_inline<size>([&](auto a) KANE_ALWAYS_INLINE_LAMBDA {
        const S norm2 = block.row(Eigen::Index(a)).squaredNorm();
        out.singular = out.singular || (norm2 == norm2 && !(norm2 > tol * tol));
        inverse.col(Eigen::Index(a)) = block.row(Eigen::Index(a)).transpose() * (S(1) / norm2);
      });
      static_for_inline<size * size>([&](auto ab) KANE_ALWAYS_INLINE_LAMBDA {
        constexpr std::size_t a = ab / size, e = ab % size;
        out.inverse[Sys::form.order[first + a]][Sys::form.order[first + e]] = inverse(a, e);
      });
    } else {
      const auto f = out.f;
      const S tol = limits::epsilon() * S(n) * (scale * f);
      const auto block = scaled_block<Sys, first, size>(m, f);
      Eigen::Matrix<S, int(size), int(size)> inverse;
      if constexpr (lane_traits<S>::width > 1) {  // factor_block of lanes (lanes.hpp): false where it fails
        const auto factored = factor_block(block, inverse, tol);
        out.singular = out.singular || (!factored && all_finite_matrix(block));
      } else if (!factor_block(block, inverse, tol)) {
        out.singular = out.singular || block.allFinite();
        inverse.setConstant(limits::quiet_NaN());
      }
      static_for_inline<size * size>([&](auto ab) KANE_ALWAYS_INLINE_LAMBDA {
        constexpr std::size_t a = ab / size, e = ab % size;
        out.inverse[Sys::form.order[first + a]][Sys::form.order[first + e]] = inverse(a, e);
      });
    }
  });
  return out;
}

// X = M^-1 R from the factors of M. Sys: static constexpr n, k, m (pattern n x n), r (n x k),
// form (blocks_of(m)), x (solution_pattern). The zeros and ones of X are written unless the
// caller keeps them (known_entries::left). checking::at_end: X is not checked finite (the caller
// checks what it computes from X). C is an argument, folded where the call inlines: one
// instantiation serves both checks.
template <class Sys, known_entries Known, class S>
KANE_ALWAYS_INLINE status_of<S> substitute_structured_as(const table<S, Sys::n, Sys::n>& m,
                                                         const structured_factors<S, Sys::n>& fac,
                                                         const table<S, Sys::n, Sys::k>& r,
                                                         table<S, Sys::n, Sys::k>& x, checking C) {
  using limits = std::numeric_limits<S>;
  constexpr std::size_t n = Sys::n, k = Sys::k;
  auto rhs = [&](auto i, auto j) -> S {
    if constexpr (Sys::r[i][j] == entry::zero)
      return S(0);
    else if constexpr (Sys::r[i][j] == entry::one)
      return S(1);
    else
      return r[i][j];
  };
  static_for_inline<n * k>([&](auto cj) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t c = cj / k, j = cj % k;
    if constexpr (Known == known_entries::written && Sys::x[c][j] != entry::other)
      x[c][j] = S(Sys::x[c][j] == entry::one);
  });
  static_for_inline<Sys::form.count>([&](auto b) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t first = Sys::form.start[b], size = Sys::form.start[b + 1] - first;
    // t_j = R_{row c, j} - sum over unknowns d of earlier blocks of M_{row c, d} x_dj
    auto reduced = [&](auto c, auto j) {
      constexpr std::size_t row = Sys::form.row[c];
      S t = rhs(index_c<row>{}, j);
      // a fold, no function a term; x_dj = 1 from the pattern (known_entries::left leaves it unwritten)
      [&]<std::size_t... d>(std::index_sequence<d...>) KANE_ALWAYS_INLINE_LAMBDA {
        (void(Sys::form.block[d] != b && Sys::m[row][d] != entry::zero && Sys::x[d][j] != entry::zero
                  ? t -= Sys::m[row][d] == entry::one
                             ? (Sys::x[d][j] == entry::one ? S(1) : x[d][j])
                             : S(m[row][d] * (Sys::x[d][j] == entry::one ? S(1) : x[d][j]))
                  : t),
         ...);
      }
      (std::make_index_sequence<n>{});
      return t;
    };
    if constexpr (size == 1) {
      constexpr std::size_t c = Sys::form.order[first], row = Sys::form.row[c];
      static_for_inline<k>([&](auto j) KANE_ALWAYS_INLINE_LAMBDA {
        if constexpr (Sys::x[c][j] == entry::other) {
          const S t = reduced(index_c<c>{}, j);
          if constexpr (Sys::m[row][c] == entry::one)
            x[c][j] = t;
          else
            x[c][j] = t / m[row][c];
        }
      });
    } else {
      const auto block = scaled_block<Sys, first, size>(m, fac.f);
      Eigen::Matrix<S, int(size), int(size)> inverse;  // (f M_B)^-1, column after column in blocks
      store_in_blocks<size * size>(inverse.data(), [&](auto ea) KANE_ALWAYS_INLINE_LAMBDA {
        constexpr std::size_t a = ea % size, e = ea / size;
        return fac.inverse[Sys::form.order[first + a]][Sys::form.order[first + e]];
      });
      static_for_inline<k>([&](auto j) KANE_ALWAYS_INLINE_LAMBDA {
        if constexpr (Sys::x[Sys::form.order[first]][j] != entry::zero) {
          Eigen::Matrix<S, int(size), 1> t;
          static_for_inline<size>([&](auto a) KANE_ALWAYS_INLINE_LAMBDA {
            t(Eigen::Index(a)) = reduced(index_c<Sys::form.order[first + a]>{}, j) * fac.f;
          });
          const Eigen::Matrix<S, int(size), 1> y = solve_block(inverse, block, t);  // (f M)^-1 f t
          static_for_inline<size>([&](auto a) KANE_ALWAYS_INLINE_LAMBDA {
            x[Sys::form.order[first + a]][j] = y(Eigen::Index(a));
          });
        }
      });
    }
  });
  S residue = -S(0);  // x - x is 0 for a finite x, NaN otherwise
  if (C == checking::each)
    static_for_inline<n * k>([&](auto cj) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t c = cj / k, j = cj % k;
      if constexpr (Sys::x[c][j] == entry::other) residue += x[c][j] - x[c][j];
    });
  const auto status = checks<S>(fac.scale <= limits::max(), solve_status::not_finite, !fac.singular,
                                solve_status::singular, residue == S(0), solve_status::not_finite);
  const auto spoil = nan_unless_rare<S>(ok_of<S>(status));
  static_for_inline<n * k>([&](auto cj) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t c = cj / k, j = cj % k;
    if constexpr (Sys::x[c][j] == entry::other) spoil(x[c][j]);
  });
  return status;
}
template <class Sys, known_entries Known = known_entries::written, checking C = checking::each, class S>
KANE_ALWAYS_INLINE status_of<S> substitute_structured(const table<S, Sys::n, Sys::n>& m,
                                                      const structured_factors<S, Sys::n>& fac,
                                                      const table<S, Sys::n, Sys::k>& r,
                                                      table<S, Sys::n, Sys::k>& x) {
  return substitute_structured_as<Sys, Known>(m, fac, r, x, C);
}

template <class Sys, known_entries Known = known_entries::written, class S>
KANE_ALWAYS_INLINE status_of<S> solve_structured(const table<S, Sys::n, Sys::n>& m,
                                                 const table<S, Sys::n, Sys::k>& r,
                                                 table<S, Sys::n, Sys::k>& x) {
  return substitute_structured<Sys, Known>(m, factor_structured<Sys>(m), r, x);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
