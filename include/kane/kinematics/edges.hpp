// The edge kinds of a frame tree and what each contributes to angular
// velocities: a simple rotation by an angle theta about k
// (^P w^C = theta' k), Euler parameters, a spin at a free speed (u k), an
// attitude read from the state (three free speeds along C's or P's axes);
// and the partial angular velocities d(^A w^B)/dq_r' and d(^A w^B)/du_r.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "kane/detail/choices.hpp"
#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/frames/axis.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class X>
constexpr auto ddt(X x);  // derivative.hpp
template <class Leaf, class X>
constexpr auto partial(X x);

// The edge above X: ^P w^X = sum_i w_i x_i. For Euler parameters (q0, ..., q3)
// (SymPy's 'Quaternion' orientation), (w1, w2, w3) = 2 (q0 v' - q0' v - v x v'), v = (q1, q2, q3).
template <class X>
inline constexpr bool euler_edge = requires {
  X::step::coordinates;
};
// ^P w^X = u_r k for X spinning by a free speed (frames/orientation.hpp, spin).
template <class X>
inline constexpr bool spin_edge = requires {
  X::step::speed_index;
};
// ^P P^C from the state, ^P w^C from three free speeds (frames/orientation.hpp, attitude).
template <class X>
inline constexpr bool attitude_edge = requires {
  X::step::rate_speeds;
};
// An edge with no axis: its matrix read from the state, ^P w^C = sum_i w_i k_i.
template <class X>
inline constexpr bool matrix_edge = euler_edge<X> || attitude_edge<X>;
template <class X>
constexpr auto quaternion_rates() {
  constexpr auto c = X::step::coordinates;
  constexpr coordinate<c[0]> a{};
  constexpr coordinate<c[1]> b{};
  constexpr coordinate<c[2]> g{};
  constexpr coordinate<c[3]> h{};
  constexpr auto da = ddt(a);
  constexpr auto db = ddt(b);
  constexpr auto dg = ddt(g);
  constexpr auto dh = ddt(h);
  constexpr constant<2> two{};
  return std::tuple{two * (a * db - b * da - g * dh + h * dg), two * (a * dg + b * dh - g * da - h * db),
                    two * (a * dh - b * dg + g * db - h * da)};
}

// k of the edge above X: X's axis if principal, else by its components in U (X or its parent).
template <class X, class U = X>
constexpr auto axis_vector() {
  using K = typename X::step::axis;
  constexpr int p = unit_axis<K>::principal;
  constexpr auto k = unit_axis<K>::value;
  if constexpr (p >= 0)
    return unit<X, p + 1>{};
  else
    return fixed<literal(k[0])>{} * unit<U, 1>{} + fixed<literal(k[1])>{} * unit<U, 2>{} +
           fixed<literal(k[2])>{} * unit<U, 3>{};
}

// d(^P w^X)/dq_R', a vector in X: d(theta)/dq_R k for a simple rotation by theta about k.
template <std::size_t R, class X>
constexpr auto edge_axis() {
  if constexpr (spin_edge<X> || attitude_edge<X>)
    return zero_vector{};
  else if constexpr (euler_edge<X>) {
    constexpr auto w = quaternion_rates<X>();
    using r = coordinate<R, 1>;
    return partial<r>(std::get<0>(w)) * unit<X, 1>{} + partial<r>(std::get<1>(w)) * unit<X, 2>{} +
           partial<r>(std::get<2>(w)) * unit<X, 3>{};
  } else {
    constexpr auto d = partial<coordinate<R>>(X::step::angle);
    constexpr auto axis = axis_vector<X>();
    if constexpr (std::is_same_v<decltype(d), const zero_t>)
      return zero_vector{};
    else if constexpr (std::is_same_v<decltype(d), const one_t>)
      return axis;
    else
      return d * axis;
  }
}
// d(^P w^X)/du_R: k if X spins by u_R; c_i (p_i) if u_R is the i-th body (parent) rate of an attitude.
template <std::size_t R, class X>
constexpr auto edge_spin() {
  if constexpr (spin_edge<X>) {
    if constexpr (X::step::speed_index == R)
      return axis_vector<X, typename X::tree_parent>();  // of X's axes only k is known
    else
      return zero_vector{};
  } else if constexpr (attitude_edge<X>) {
    constexpr auto s = X::step::rate_speeds;
    constexpr int i = s[0] == R ? 1 : s[1] == R ? 2 : s[2] == R ? 3 : 0;
    using F = std::conditional_t<X::step::body_rates, X, typename X::tree_parent>;
    if constexpr (i == 0)
      return zero_vector{};
    else
      return unit<F, i>{};
  } else
    return zero_vector{};
}
// The free speeds that turn the edge above X (0: none).
template <class X>
constexpr std::array<std::size_t, 3> free_speeds() {
  if constexpr (spin_edge<X>)
    return {X::step::speed_index, 0, 0};
  else if constexpr (attitude_edge<X>)
    return X::step::rate_speeds;
  else
    return {0, 0, 0};
}
// A frame that spins or has an attitude turns at free speeds of Speeds.
template <class Speeds, class F>
constexpr bool turns_freely() {
  if constexpr (!spin_edge<F> && !attitude_edge<F>)
    return true;
  else if constexpr (std::is_void_v<Speeds>)
    return false;
  else {
    bool ok = true;
    for (std::size_t i : free_speeds<F>()) ok = ok && (i == 0 || (i > Speeds::defined && i <= Speeds::n));
    return ok;
  }
}
template <class Speeds, class... F>
constexpr bool free_speeds_checked(list<F...>) {
  return (
      check<turns_freely<Speeds, F>(), error::a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<F>> &&
      ...);
}
// d(^A w^B)/dq_R' or d(^A w^B)/du_R over the path A -> B.
template <std::size_t R, wrt By = wrt::rates, class... Up, class... Down>
constexpr auto partial_omega(list<Up...>, list<Down...>) {
  if constexpr (By == wrt::speeds)
    return (zero_vector{} - ... - edge_spin<R, Up>()) + (zero_vector{} + ... + edge_spin<R, Down>());
  else
    return (zero_vector{} - ... - edge_axis<R, Up>()) + (zero_vector{} + ... + edge_axis<R, Down>());
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
