// Finiteness tests without a comparison per number: x - x is 0 for a finite x and NaN for NaN or
// inf, and a sum of such residues is 0 exactly when every number is finite. One double state's
// results are tested by their exponent bits instead (finite_bits).
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/wide_stores.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
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
// One state of doubles: true where every number of the fixed-size matrix m and of a is finite.
// The exponent bits of x plus one in their lowest place set the sign bit exactly where they are all
// set; or-ed, every step is an integer one, shorter than the floating-point x - x and sum.
template <class M, std::size_t N = 0>
KANE_ALWAYS_INLINE bool finite_bits(const M& m, const std::array<double, N>& a = {}) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000, one = 0x0010000000000000;
  std::uint64_t bad = 0;
  const auto add = [&](double x) KANE_ALWAYS_INLINE_LAMBDA {
    bad |= (std::bit_cast<std::uint64_t>(x) & exponent) + one;
  };
  static_for_inline<N>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { add(a[i]); });
  static_for_inline<std::size_t(M::SizeAtCompileTime)>(
      [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { add(m.coeff(std::ptrdiff_t(i))); });
  return (bad >> 63) == 0;
}
// The nonfinite_residue of a state's arrays. InBlocks: their owner stored them in blocks
// (detail/wide_stores.hpp); then six doubles or more are read in those blocks into one vector sum,
// reduced once.
template <bool InBlocks, class S, std::size_t... N>
KANE_ALWAYS_INLINE S input_residue(const std::array<S, N>&... a) {
  if constexpr (InBlocks && std::is_same_v<S, double> && (0 + ... + N) >= 6) {
    constexpr std::size_t w = widest_store;
    using wide_block = typename block_of<w>::type;
    using pair = typename block_of<2>::type;
    wide_block sum = -wide_block{};  // -0: the identity the optimizer folds away
    pair half = -pair{};
    double one = -0.0;
    const auto add = [&]<std::size_t M>(const std::array<double, M>& x) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t wide = M / w * w, pairs = wide + (M - wide) / 2 * 2;
      for (std::size_t k = 0; k < wide; k += w) {
        wide_block b;
        std::memcpy(&b, x.data() + k, sizeof b);
        sum += b - b;
      }
      if constexpr (pairs > wide) {
        pair b;
        std::memcpy(&b, x.data() + wide, sizeof b);
        half += b - b;
      }
      if constexpr (M > pairs) one += x[pairs] - x[pairs];
    };
    (add(a), ...);
    half += __builtin_shufflevector(sum, sum, 0, 1);
    if constexpr (w > 2) half += __builtin_shufflevector(sum, sum, w - 2, w - 1);
    return half[0] + half[1] + one;
  } else
    return (S(-0.0) + ... + nonfinite_residue(a));
}
// Reads::in_blocks: the state's arrays were stored in blocks (detail/wide_stores.hpp)
template <class Reads>
inline constexpr bool reads_in_blocks = requires {
  Reads::in_blocks;
};
// The residue of a state's t, q and p, with u where U and u' where Ud (input_residue).
template <bool InBlocks, bool U, bool Ud, class St>
KANE_ALWAYS_INLINE auto state_residue(const St& s) {
  const auto t = s.t - s.t;
  if constexpr (U && Ud)
    return t + input_residue<InBlocks>(s.q, s.p, s.u, s.ud);
  else if constexpr (U)
    return t + input_residue<InBlocks>(s.q, s.p, s.u);
  else
    return t + input_residue<InBlocks>(s.q, s.p);
}
template <class S, std::size_t N>
constexpr auto all_finite(const std::array<S, N>& a) {
  return nonfinite_residue(a) == S(0);
}
// The same for an Eigen matrix of fixed size: one sum, no branch per entry.
template <class M>
auto all_finite_matrix(const M& m) {
  return (m.array() - m.array()).sum() == typename M::Scalar(0);
}
// The nonfinite_residue of a fixed-size Eigen matrix, pairwise.
template <class M>
KANE_ALWAYS_INLINE auto matrix_residue(const M& m) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return nonfinite_residue(std::array<typename M::Scalar, sizeof...(I)>{m.coeff(std::ptrdiff_t(I))...});
  }
  (std::make_index_sequence<std::size_t(M::SizeAtCompileTime)>{});
}
// The same number by number, for a small matrix whose numbers were just stored one by one: a
// wide load of them would wait.
template <class M>
auto all_finite_numbers(const M& m) {
  if constexpr (M::SizeAtCompileTime > 16)
    return all_finite_matrix(m);
  else
    return matrix_residue(m) == typename M::Scalar(0);
}
// The diagonal of a mass matrix M finite: so is all of M, |M_rs| <= (M_rr M_ss)^1/2 (M positive
// semidefinite).
template <class M>
auto finite_diagonal(const M& m) {
  using S = typename M::Scalar;
  return [&]<int... I>(std::integer_sequence<int, I...>) { return ((m(I, I) - m(I, I)) + ...) == S(0); }
  (std::make_integer_sequence<int, M::RowsAtCompileTime>{});
}
// A mass matrix finite: its diagonal for numbers and lanes, every entry for jets.
template <class M>
auto finite_masses(const M& m) {
  using S = typename M::Scalar;
  if constexpr (std::is_floating_point_v<S> || lane_traits<S>::width > 1)
    return finite_diagonal(m);
  else
    return all_finite_matrix(m);
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
