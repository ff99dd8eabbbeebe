// Generalized speeds u_r = sum_s Y_rs(q, t) q_s' + Z_r(q, t).
//
//   kane::qdot_speeds<6>                       u_r = q_r'
//   kane::speeds<dot(w, e<L, 1>), ...>         any n expressions linear in q'
//   kane::angular_velocity_speeds<N, R, L>     u_i = ^N w^R . l_i
//   kane::speeds<dt(q<1>), kane::free_speed>   u_1 = q_1', u_2 free (a spin rate)
//   kane::free_body_speeds<N, B, 5>            body rates of B, then q_5', q_6', q_7', unit_norm<B>
//
// Y_rs = du_r/dq_s' and Z_r = u_r at q' = 0 are built at compile time; the evaluator solves the kinematic
// differential equations at each state: q' = W u + X, W = Y^-1, X = -Y^-1 Z, and q'' = W (u' - Y' q' - Z').
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/structure.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/speeds/component_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct speed_set_tag {};
}  // namespace detail

template <class T>
concept SpeedSet = std::derived_from<T, detail::speed_set_tag>;

// u_r = q_r', r = 1..N.
template <std::size_t N>
struct qdot_speeds : detail::speed_set_tag {
  // n = rows = defined = N: N speeds, each defined by a q'
  static constexpr std::size_t n = N, rows = N, defined = N;
  // true: Y = W = 1, X = 0
  static constexpr bool identity = true;
};

// A kinematic differential equation that defines no speed: X = 0, linear in q'
// (for instance unit_norm of the Euler parameters of B, so that nq = nu + 1).
template <ScalarExpr X>
struct held {
  // the expression, linear in q'
  [[no_unique_address]] X x;
  // the row v = 0
  constexpr explicit held(X v) : x(v) {}
};

namespace detail {
struct free_speed_t {};
}  // namespace detail

// A speed that defines no q': the rate of a frame that spins (kane::spin), listed after the speeds q' define.
inline constexpr detail::free_speed_t free_speed{};

namespace detail {
template <class T>
inline constexpr bool is_held = false;
template <class X>
inline constexpr bool is_held<held<X>> = true;
template <class X>
inline constexpr bool is_held<const held<X>> = true;
// 0 a speed defined by q', 1 a free speed, 2 a held row
template <class T>
inline constexpr int speed_kind = is_held<T>                                          ? 2
                                  : std::is_same_v<std::remove_cv_t<T>, free_speed_t> ? 1
                                                                                      : 0;
template <class T>
constexpr auto row_of(T x) {
  if constexpr (is_held<T>)
    return x.x;
  else
    return x;
}
template <int... Kind>
constexpr bool kinds_in_order() {
  int last = 0;
  bool ok = true;
  for (int k : {0, Kind...}) ok = ok && k >= last, last = k;
  return ok;
}
}  // namespace detail

// u_r = U_r, r = 1..defined: expressions in q, q' and t, linear in q'; then free speeds (kane::free_speed),
// u_r, r = defined + 1..n; then held rows (kinematic equations without a speed): rows = defined + held = nq.
template <auto... U>
struct speeds : detail::speed_set_tag {
  static_assert(((ScalarExpr<decltype(U)> || detail::speed_kind<decltype(U)> != 0) && ...),
                "kane: speeds<u1, ..., un> takes scalar expressions");
  static_assert(detail::kinds_in_order<detail::speed_kind<decltype(U)>...>(),
                "kane: in speeds<...> the speeds that q' define come first, then kane::free_speed, then held "
                "rows (kane::held, kane::unit_norm)");
  // the number of speeds defined by q'
  static constexpr std::size_t defined = (std::size_t(detail::speed_kind<decltype(U)> == 0) + ... + 0);
  // the number of free speeds
  static constexpr std::size_t free = (std::size_t(detail::speed_kind<decltype(U)> == 1) + ... + 0);
  // the number of kinematic equations: defined + held = nq
  static constexpr std::size_t rows = sizeof...(U) - free;
  // the number of speeds: defined + free
  static constexpr std::size_t n = defined + free;
  // false: Y is built from the definitions
  static constexpr bool identity = false;
  // the rows in order: U_r of the defined speeds, then the held rows
  static constexpr auto definitions = []<std::size_t... R>(std::index_sequence<R...>) {
    constexpr std::tuple<decltype(U)...> all{U...};
    return std::tuple{detail::row_of(std::get<(R < defined ? R : R + free)>(all))...};
  }
  (std::make_index_sequence<rows>{});
};

// q0 q0' + q1 q1' + q2 q2' + q3 q3' = 0, half the derivative of |e|^2 = 1 for
// the Euler parameters of B: the held row that completes three speeds of B.
template <Frame B>
inline constexpr auto unit_norm = [] {
  if constexpr (detail::euler_edge<B>) {
    constexpr auto c = B::step::coordinates;
    constexpr coordinate<c[0]> a{};
    constexpr coordinate<c[1]> b{};
    constexpr coordinate<c[2]> g{};
    constexpr coordinate<c[3]> h{};
    return held(a * dt(a) + b * dt(b) + g * dt(g) + h * dt(h));
  } else {
    static_assert(detail::refused<error::unit_norm_needs_a_frame_oriented_by_euler_parameters<B>>);
    return held(zero_t{});
  }
}();

// u_1..u_3 = ^A w^B . f_1..3 (the components of ^A w^B in F), then Extra... (such as kane::dt(kane::q<4>)).
template <class A, class B, class F, auto... Extra>
using angular_velocity_speeds =
    speeds<dot(angular_velocity<A, B>(), e<F, 1>), dot(angular_velocity<A, B>(), e<F, 2>),
           dot(angular_velocity<A, B>(), e<F, 3>), Extra...>;

// A free body B on Euler parameters, its mass centre at q_P n1 + q_P+1 n2 + q_P+2 n3 of N: the body
// rates u_1..u_3 = ^N w^B . b_i, then u_4..u_6 = q_P', q_P+1', q_P+2', and unit_norm<B>.
template <class N, class B, std::size_t P>
using free_body_speeds =
    speeds<dot(angular_velocity<N, B>(), e<B, 1>), dot(angular_velocity<N, B>(), e<B, 2>),
           dot(angular_velocity<N, B>(), e<B, 3>), dt(coordinate<P>{}), dt(coordinate<P + 1>{}),
           dt(coordinate<P + 2>{}), unit_norm<B>>;
// q_P n1 + q_P+1 n2 + q_P+2 n3: a position by three coordinates along N's axes.
template <class N, std::size_t P>
inline constexpr auto position_coordinates =
    coordinate<P>{} * e<N, 1> + coordinate<P + 1>{} * e<N, 2> + coordinate<P + 2>{} * e<N, 3>;

}  // namespace kane
#pragma GCC diagnostic pop
