// A runtime state: plain, fixed-size, allocation-free.
#pragma once

#include <array>
#include <cstddef>

#include "kane/fwd.hpp"
#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/scalar.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The inputs of a state without any: no storage.
template <class S>
struct no_inputs {
  static constexpr std::size_t size() { return 0; }
  constexpr bool operator==(const no_inputs&) const = default;
};
}  // namespace detail

// q_1..q_NQ at q[0..NQ-1] with their first and second time derivatives qd,
// qdd; generalized speeds u and their derivatives ud; parameters p; time t;
// inputs r (read by loads only).
// An aggregate: value-initialised to zero, trivially copyable, no heap.
template <class S, std::size_t NQ, std::size_t NU = NQ, std::size_t NP = 0, std::size_t NR = 0>
struct state {
  static_assert(Scalar<S>, "kane: state<S, NQ, ...> needs a scalar type S (float, double, ...)");
  // the scalar type S
  using scalar = S;
  // the number of coordinates q_i
  static constexpr std::size_t nq = NQ;
  // the number of generalized speeds u_i
  static constexpr std::size_t nu = NU;
  // the number of parameters p_i
  static constexpr std::size_t np = NP;
  // the number of inputs r_i
  static constexpr std::size_t nr = NR;

  // q_1..q_NQ
  std::array<S, NQ> q{};
  // q_1'..q_NQ'
  std::array<S, NQ> qd{};
  // q_1''..q_NQ''
  std::array<S, NQ> qdd{};
  // u_1..u_NU
  std::array<S, NU> u{};
  // u_1'..u_NU'
  std::array<S, NU> ud{};
  // p_1..p_NP
  std::array<S, NP> p{};
  // the storage of r: NR numbers, none for NR = 0
  using inputs_type = std::conditional_t<NR == 0, detail::no_inputs<S>, std::array<S, NR>>;
  // r_1..r_NR
  [[no_unique_address]] inputs_type r{};
  // the time t
  S t{};

  // s[coordinate<I, D>{}]: q_I, q_I' or q_I'' (s[q<1>] is q[0])
  template <std::size_t I, std::size_t D>
  S& operator[](coordinate<I, D>) {
    return pick<I, D>(*this);
  }
  // q_I, q_I' or q_I'' of a const state
  template <std::size_t I, std::size_t D>
  const S& operator[](coordinate<I, D>) const {
    return pick<I, D>(*this);
  }
  // s[speed<I, D>{}]: u_I or u_I' (s[u<1>] is u[0])
  template <std::size_t I, std::size_t D>
  S& operator[](speed<I, D>) {
    return pick_u<I, D>(*this);
  }
  // u_I or u_I' of a const state
  template <std::size_t I, std::size_t D>
  const S& operator[](speed<I, D>) const {
    return pick_u<I, D>(*this);
  }
  // s[P{}] for a parameter P derived from parameter<k>: p_k
  template <std::size_t I>
  S& operator[](parameter<I>) {
    return pick_p<I>(*this);
  }
  // p_k of a const state
  template <std::size_t I>
  const S& operator[](parameter<I>) const {
    return pick_p<I>(*this);
  }
  // s[input<k>{}]: r_k (s[r<1>] is r[0])
  template <std::size_t I>
  S& operator[](input<I>) {
    return pick_r<I>(*this);
  }
  // r_k of a const state
  template <std::size_t I>
  const S& operator[](input<I>) const {
    return pick_r<I>(*this);
  }

 private:
  template <std::size_t I, std::size_t D, class Self>
  static auto& pick(Self& s) {
    static_assert(I <= NQ, "kane: this coordinate is beyond the state; declare the state with NQ >= I");
    static_assert(D <= 2, "kane: a state holds q, q' and q'' only");
    if constexpr (D == 0)
      return s.q[I - 1];
    else if constexpr (D == 1)
      return s.qd[I - 1];
    else
      return s.qdd[I - 1];
  }
  template <std::size_t I, std::size_t D, class Self>
  static auto& pick_u(Self& s) {
    static_assert(I <= NU, "kane: this speed is beyond the state; declare the state with NU >= I");
    static_assert(D <= 1, "kane: a state holds u and u' only");
    if constexpr (D == 0)
      return s.u[I - 1];
    else
      return s.ud[I - 1];
  }
  template <std::size_t I, class Self>
  static auto& pick_p(Self& s) {
    static_assert(I <= NP, "kane: this parameter is beyond the state; declare the state with NP >= I");
    return s.p[I - 1];
  }
  template <std::size_t I, class Self>
  static auto& pick_r(Self& s) {
    static_assert(I <= NR, "kane: this input is beyond the state; declare the state with NR >= I");
    return s.r[I - 1];
  }
};

namespace detail {
template <class T>
struct is_state : std::false_type {};
template <class S, std::size_t NQ, std::size_t NU, std::size_t NP, std::size_t NR>
struct is_state<state<S, NQ, NU, NP, NR>> : std::true_type {};
}  // namespace detail

template <class T>
concept State = detail::is_state<T>::value;

}  // namespace kane
#pragma GCC diagnostic pop
