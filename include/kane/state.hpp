// A runtime state: plain, fixed-size, allocation-free.
#pragma once

#include <array>
#include <cstddef>

#include "kane/coordinate.hpp"
#include "kane/fwd.hpp"
#include "kane/scalar.hpp"

namespace kane {

// q_1..q_NQ at q[0..NQ-1], generalized speeds u, parameters p and time t.
// An aggregate: value-initialised to zero, copyable, no heap.
template <class S, std::size_t NQ, std::size_t NU = NQ, std::size_t NP = 0>
struct state {
  static_assert(Scalar<S>, "kane: state<S, NQ, ...> needs a scalar type S (float, double, ...)");
  using scalar = S;
  static constexpr std::size_t nq = NQ;
  static constexpr std::size_t nu = NU;
  static constexpr std::size_t np = NP;

  std::array<S, NQ> q{};
  std::array<S, NU> u{};
  std::array<S, NP> p{};
  S t{};

  template <std::size_t I>
  S& operator[](coordinate<I>) {
    static_assert(I <= NQ, "kane: this coordinate is beyond the state; declare the state with NQ >= I");
    return q[I - 1];
  }
  template <std::size_t I>
  const S& operator[](coordinate<I>) const {
    static_assert(I <= NQ, "kane: this coordinate is beyond the state; declare the state with NQ >= I");
    return q[I - 1];
  }
};

namespace detail {
template <class T>
struct is_state : std::false_type {};
template <class S, std::size_t NQ, std::size_t NU, std::size_t NP>
struct is_state<state<S, NQ, NU, NP>> : std::true_type {};
}  // namespace detail

template <class T>
concept State = detail::is_state<T>::value;

}  // namespace kane
