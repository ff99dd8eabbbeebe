// Numbers stored in blocks. A wide load of numbers that were stored one by one waits until each
// store has left the store buffer; a load of a block stored whole is forwarded. The compiler's
// copies of small objects and Eigen's fixed-size products read doubles in such blocks.
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The widest store of doubles here: the width of the compiler's copies of small objects.
#ifdef __AVX__
inline constexpr std::size_t widest_store = 4;
#else
inline constexpr std::size_t widest_store = 2;
#endif

// W doubles in one register
template <std::size_t W>
struct block_of;
template <>
struct block_of<2> {
  using type = double __attribute__((vector_size(16)));
};
template <>
struct block_of<4> {
  using type = double __attribute__((vector_size(32)));
};

// value(First), ..., value(First + W - 1) stored whole at to + First: W doubles.
template <std::size_t First, std::size_t W, class F>
KANE_ALWAYS_INLINE void store_block(double* to, const F& value) {
  using block = typename block_of<W>::type;
  const block b = [&]<std::size_t... K>(std::index_sequence<K...>) KANE_ALWAYS_INLINE_LAMBDA {
    return block{double(value(std::integral_constant<std::size_t, First + K>{}))...};
  }
  (std::make_index_sequence<W>{});
  std::memcpy(to + First, &b, sizeof b);
}

// to[i] = value(std::integral_constant<std::size_t, i>{}) for i < N: doubles in stores of
// widest_store numbers from to[0], then of two and one, as a copy of N doubles reads them.
template <std::size_t N, class S, class F>
KANE_ALWAYS_INLINE void store_in_blocks(S* to, const F& value) {
  if constexpr (std::is_same_v<S, double>) {
    constexpr std::size_t wide = N / widest_store * widest_store, pairs = wide + (N - wide) / 2 * 2;
    [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      (store_block<I * widest_store, widest_store>(to, value), ...);
    }
    (std::make_index_sequence<N / widest_store>{});
    if constexpr (pairs > wide) store_block<wide, 2>(to, value);
    if constexpr (N > pairs) to[pairs] = value(std::integral_constant<std::size_t, pairs>{});
  } else
    [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      ((to[I] = value(std::integral_constant<std::size_t, I>{})), ...);
    }
  (std::make_index_sequence<N>{});
}

// The entries of a small matrix that are zero at compile time, by rows: none by default.
template <std::size_t Rows, std::size_t Cols>
struct zero_pattern {
  std::array<bool, Rows * Cols> zero{};
};

template <auto Zeros, int Inner>
constexpr bool zero_entry(int r, int k) {
  if constexpr (Zeros.zero.size() == 0)
    return false;
  else
    return Zeros.zero[std::size_t(r * Inner + k)];
}
template <auto Zeros, int Inner>
constexpr int first_entry(int r) {  // the first entry of row r not zero, or Inner
  int k = 0;
  while (k < Inner && zero_entry<Zeros, Inner>(r, k)) ++k;
  return k;
}
// (a b)_RC = sum over k of a_Rk b_kC in ascending order, Zeros' entries of a skipped
template <auto Zeros, int R, int C, class A, class B>
KANE_ALWAYS_INLINE typename A::Scalar product_entry(const A& a, const B& b) {
  using S = typename A::Scalar;
  constexpr int inner = A::ColsAtCompileTime, first = first_entry<Zeros, inner>(R);
  if constexpr (first == inner)
    return S(0);
  else {
    S x = a.coeff(R, first) * b.coeff(first, C);
    [&]<int... K>(std::integer_sequence<int, K...>) KANE_ALWAYS_INLINE_LAMBDA {
      ((K > first_entry<Zeros, A::ColsAtCompileTime>(R) && !zero_entry<Zeros, A::ColsAtCompileTime>(R, K)
            ? void(x += a.coeff(R, K) * b.coeff(K, C))
            : void()),
       ...);
    }
    (std::make_integer_sequence<int, inner>{});
    return x;
  }
}

// a b of small fixed sizes, each number a sum over k in ascending order of numbers read one by
// one: no wide load of a or b, which were often just stored number by number. The entries of a
// that Zeros marks skip their products. A matrix is stored in blocks.
template <auto Zeros = zero_pattern<0, 0>{}, class A, class B>
KANE_ALWAYS_INLINE Eigen::Matrix<typename A::Scalar, A::RowsAtCompileTime, B::ColsAtCompileTime>
product_in_blocks(const A& a, const B& b) {
  using S = typename A::Scalar;
  constexpr int rows = A::RowsAtCompileTime;
  Eigen::Matrix<S, rows, B::ColsAtCompileTime> out;
  const auto number = [&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
    return product_entry<Zeros, int(i) % A::RowsAtCompileTime, int(i) / A::RowsAtCompileTime>(a, b);
  };
  constexpr std::size_t size = std::size_t(rows * B::ColsAtCompileTime);
  if constexpr (B::ColsAtCompileTime == 1)  // a vector, kept in registers
    [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      ((out.coeffRef(Eigen::Index(I)) = number(std::integral_constant<std::size_t, I>{})), ...);
    }
  (std::make_index_sequence<size>{});
  else store_in_blocks<size>(out.data(), number);
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
