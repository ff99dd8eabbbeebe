// What a numeric solve found: ok, a singular matrix (a pivot at or below the
// rank threshold), numbers that are not finite (NaN or inf in or out), an
// iteration that did not reach its tolerance (configuration.hpp), an
// attitude read from the state that is not a rotation (kane::attitude), or a
// container of another size than the call needs (kane::motion), or q' and u
// (q'' and u') given as different numbers where u is q' (no speed set).
// ok promises finite numbers: the promise rests on IEEE comparisons with NaN,
// which -ffast-math and -ffinite-math-only let the compiler fold away, so
// those flags are an error here unless KANE_ALLOW_FAST_MATH is defined (then
// status() may say ok for NaN or infinite numbers).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/wide_stores.hpp"

#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) && \
    !defined(KANE_ALLOW_FAST_MATH)
#error "kane: finite math only (-ffast-math) voids solve_status: build without or define KANE_ALLOW_FAST_MATH"
#endif

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// ok, a singular matrix, numbers not finite, no convergence, an attitude not a rotation, a
// container of the wrong size, or q' and u that disagree where u is q'
enum class solve_status {
  ok,
  singular,
  not_finite,
  not_converged,
  not_a_rotation,
  wrong_size,
  conflicting_rates
};
// The name of a status ("ok", "singular", ...).
constexpr const char* to_string(solve_status s) {
  switch (s) {
    case solve_status::ok:
      return "ok";
    case solve_status::singular:
      return "singular";
    case solve_status::not_finite:
      return "not_finite";
    case solve_status::not_converged:
      return "not_converged";
    case solve_status::not_a_rotation:
      return "not_a_rotation";
    case solve_status::wrong_size:
      return "wrong_size";
    case solve_status::conflicting_rates:
      return "conflicting_rates";
  }
  return "unknown";
}

namespace detail {
// 0 if every number of a is finite, NaN otherwise: x - x is 0 for a finite x and
// NaN for NaN or inf, and a sum of zeros is 0 (no comparison per number). The sum is
// pairwise, so its additions do not wait on each other. An empty sum is -0, the additive
// identity the optimizer folds away (x + 0 is not x for x = -0).
template <std::size_t B, std::size_t E, class S, std::size_t N>
constexpr S pairwise_residue(const std::array<S, N>& a) {
  if constexpr (E - B == 1)
    return a[B] - a[B];
  else
    return pairwise_residue<B, B + (E - B) / 2>(a) + pairwise_residue<B + (E - B) / 2, E>(a);
}
template <class S, std::size_t N>
constexpr S nonfinite_residue(const std::array<S, N>& a) {
  if constexpr (N == 0)
    return -S(0);
  else
    return pairwise_residue<0, N>(a);
}
// spoil(x) makes x (an S or a matrix of S) NaN unless ok: for numbers a product
// by 1 or NaN (no branch, so the results need not merge), else a store.
template <class S>
KANE_ALWAYS_INLINE auto nan_unless(bool ok) {
  if constexpr (std::is_floating_point_v<S>)
    return [factor = ok ? S(1) : std::numeric_limits<S>::quiet_NaN()](auto& x) { x *= factor; };
  else
    return [ok](auto& x) {
      if (ok) return;
      const S nan = std::numeric_limits<S>::quiet_NaN();
      if constexpr (requires { x.setConstant(nan); })
        x.setConstant(nan);
      else
        x = nan;
    };
}
// x (a fixed-size Eigen matrix) NaN unless ok, as nan_unless; doubles rewritten in blocks
// (detail/wide_stores.hpp), which a copy of x reads whole.
template <class M>
KANE_ALWAYS_INLINE void spoil_unless(M& x, bool ok) {
  using S = typename M::Scalar;
  if constexpr (std::is_floating_point_v<S> && std::is_base_of_v<Eigen::PlainObjectBase<M>, M>) {
    const S factor = ok ? S(1) : std::numeric_limits<S>::quiet_NaN();
    store_in_blocks<std::size_t(M::SizeAtCompileTime)>(
        x.data(), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { return S(x.coeff(std::ptrdiff_t(i)) * factor); });
  } else
    nan_unless<S>(ok)(x);
}
template <class S, std::size_t N>
constexpr bool all_finite(const std::array<S, N>& a) {
  return nonfinite_residue(a) == S(0);
}
// The same for an Eigen matrix of fixed size: one sum, no branch per entry.
template <class M>
bool all_finite_matrix(const M& m) {
  return (m.array() - m.array()).sum() == typename M::Scalar(0);
}
// The same number by number, for a small matrix whose numbers were just stored one by one: a
// wide load of them would wait.
template <class M>
bool all_finite_numbers(const M& m) {
  if constexpr (M::SizeAtCompileTime > 16)
    return all_finite_matrix(m);
  else
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      return all_finite(std::array<typename M::Scalar, sizeof...(I)>{m.coeff(std::ptrdiff_t(I))...});
    }
  (std::make_index_sequence<std::size_t(M::SizeAtCompileTime)>{});
}
// The status of a result x computed at status: not_finite where x is not, and x NaN unless ok.
template <class M>
solve_status finished(M& x, solve_status status) {
  if (status == solve_status::ok && !all_finite_matrix(x)) status = solve_status::not_finite;
  if (status != solve_status::ok) x.setConstant(std::numeric_limits<typename M::Scalar>::quiet_NaN());
  return status;
}
// The diagonal of a mass matrix M finite: so is all of M, |M_rs| <= (M_rr M_ss)^1/2 (M positive
// semidefinite).
template <class M>
bool finite_diagonal(const M& m) {
  using S = typename M::Scalar;
  return [&]<int... I>(std::integer_sequence<int, I...>) { return ((m(I, I) - m(I, I)) + ...) == S(0); }
  (std::make_integer_sequence<int, M::RowsAtCompileTime>{});
}
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
