// What a linearization returns: the inputs of B, the order of x by coordinate and speed,
// the first-order model dx' = A dx + B dr and the second-order equations M u' + C u + K q = B r.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "kane/evaluation/status.hpp"
#include "kane/scalars/coordinate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// The inputs of B: parameters (kane::parameter<k>{}) or inputs of the state (kane::r<k>).
template <auto... P>
struct inputs {
  // the number of inputs
  static constexpr std::size_t n = sizeof...(P);
  // k of each parameter<k> or r<k>
  static constexpr std::array<std::size_t, n> slots{std::remove_cvref_t<decltype(P)>::index...};
  // true for an input r<k> of the state, false for a parameter
  static constexpr std::array<bool, n> of_state{Input<std::remove_cvref_t<decltype(P)>>...};
};

// Which coordinate and speed each entry of a linearization's x is: x = (q_Q[0], ..., u_U[0], ...).
// index(kane::q<i>) and index(kane::u<r>) are their rows and columns, at compile time; a
// coordinate or speed that x does not hold (a dependent one) does not compile.
template <auto Q, auto U>
struct state_order {
  // Q: the i of each q_i in x, in order
  static constexpr auto coordinates = Q;
  // U: the r of each u_r in x, after the coordinates
  static constexpr auto speeds = U;
  // the row and column of q_I in x
  template <std::size_t I>
  static constexpr Eigen::Index index(coordinate<I>) {
    constexpr std::size_t k = find(Q, I);
    static_assert(k < Q.size(), "kane: q_i is not a coordinate of this x (a dependent coordinate?)");
    return Eigen::Index(k);
  }
  // the row and column of u_R in x
  template <std::size_t R>
  static constexpr Eigen::Index index(speed<R>) {
    constexpr std::size_t k = find(U, R);
    static_assert(k < U.size(), "kane: u_r is not a speed of this x (a dependent speed?)");
    return Eigen::Index(Q.size() + k);
  }

 private:
  template <class A>
  static constexpr std::size_t find(const A& a, std::size_t i) {
    std::size_t k = 0;
    while (k < a.size() && a[k] != i) ++k;
    return k;
  }
};
namespace detail {
template <std::size_t N>
constexpr std::array<std::size_t, N> one_to() {
  std::array<std::size_t, N> a{};
  for (std::size_t i = 0; i < N; ++i) a[i] = i + 1;
  return a;
}
}  // namespace detail

// dx' = A dx + B dr; rows and columns of A by Order (state_order): lin.A(lin.index(q<4>), lin.index(u<6>)).
template <class S, std::size_t NX, std::size_t NR, class Order>
struct linear_model : Order {
  // A = dx'/dx
  Eigen::Matrix<S, int(NX), int(NX)> A;
  // B = dx'/dr
  Eigen::Matrix<S, int(NX), int(NR)> B;
  // x' at the state
  Eigen::Matrix<S, int(NX), 1> rate;  // x' at the state
  // the status of the equations at the state, or of solving the constraints (one per lane for lanes)
  status_of<S> status;
};

// M u' + C u + K q = B r: rows and the columns of M, C by speed, index(u<r>) - P; K's columns by
// coordinate, index(q<i>).
template <class S, std::size_t P, std::size_t NQ, std::size_t NR, class Order>
struct linear_equations : Order {
  // M and C, of u' and u: P x P
  Eigen::Matrix<S, int(P), int(P)> M, C;
  // K, of q: P x NQ
  Eigen::Matrix<S, int(P), int(NQ)> K;
  // B, of r: P x NR
  Eigen::Matrix<S, int(P), int(NR)> B;
  // the status of the equations at the state, or of solving the constraints (one per lane for lanes)
  status_of<S> status;
  // the row of u_R in M, C, K and B: index(u) - NQ
  template <std::size_t R>
  static constexpr Eigen::Index row(speed<R> u) {
    return Order::index(u) - Eigen::Index(NQ);
  }
};

}  // namespace kane
#pragma GCC diagnostic pop
