// Numbers stored in 16-byte pairs. A wide load of numbers that were stored one by one waits
// until each store has left the store buffer; a load of a pair stored whole is forwarded.
// Eigen's fixed-size copies and products read doubles in such pairs.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// to[i] = value(std::integral_constant<std::size_t, i>{}) for i < N: doubles by pairs.
template <std::size_t N, class S, class F>
KANE_ALWAYS_INLINE void store_by_pairs(S* to, const F& value) {
  [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
    if constexpr (std::is_same_v<S, double>) {
      using pair = double __attribute__((vector_size(16)));
      (
          [&] {
            const pair p = {double(value(std::integral_constant<std::size_t, 2 * I>{})),
                            double(value(std::integral_constant<std::size_t, 2 * I + 1>{}))};
            std::memcpy(to + 2 * I, &p, sizeof p);
          }(),
          ...);
      if constexpr (N % 2 == 1) to[N - 1] = value(std::integral_constant<std::size_t, N - 1>{});
    } else {
      ((to[2 * I] = value(std::integral_constant<std::size_t, 2 * I>{}),
        to[2 * I + 1] = value(std::integral_constant<std::size_t, 2 * I + 1>{})),
       ...);
      if constexpr (N % 2 == 1) to[N - 1] = value(std::integral_constant<std::size_t, N - 1>{});
    }
  }
  (std::make_index_sequence<N / 2>{});
}

// a b of small fixed sizes, each number a sum over k in ascending order of numbers read one by
// one: no wide load of a or b, which were often just stored number by number. A matrix is
// stored in pairs.
template <class A, class B>
KANE_ALWAYS_INLINE Eigen::Matrix<typename A::Scalar, A::RowsAtCompileTime, B::ColsAtCompileTime>
product_by_pairs(const A& a, const B& b) {
  using S = typename A::Scalar;
  constexpr int rows = A::RowsAtCompileTime, inner = A::ColsAtCompileTime;
  Eigen::Matrix<S, rows, B::ColsAtCompileTime> out;
  const auto number = [&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr Eigen::Index r = Eigen::Index(i) % rows, c = Eigen::Index(i) / rows;
    if constexpr (inner == 0)
      return S(0);
    else
      return [&]<int... K>(std::integer_sequence<int, K...>) KANE_ALWAYS_INLINE_LAMBDA {
        S x = a.coeff(r, 0) * b.coeff(0, c);
        ((x += a.coeff(r, K + 1) * b.coeff(K + 1, c)), ...);
        return x;
      }
    (std::make_integer_sequence<int, inner - 1>{});
  };
  constexpr std::size_t size = std::size_t(rows * B::ColsAtCompileTime);
  if constexpr (B::ColsAtCompileTime == 1)  // a vector, kept in registers
    [&]<std::size_t... I>(std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      ((out.coeffRef(Eigen::Index(I)) = number(std::integral_constant<std::size_t, I>{})), ...);
    }
  (std::make_index_sequence<size>{});
  else store_by_pairs<size>(out.data(), number);
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
