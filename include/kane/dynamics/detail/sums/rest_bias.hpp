// An acceleration at u' = 0 as an expression (the bias of Kane's sums at rest), for the speed set
// Sp (void: u = q'): u' is zero, and so is q_i'' where a speed is q_i'. Angular accelerations that
// the speeds give are written out (component_speeds.hpp): ^R alpha^F = ^R w^G x ^R w^F where
// ^R w^F = sum u g_i, g_i fixed in G; below a frame P, ^R alpha^P + ^R w^P x ^P w^F for a spin
// u k, and + q' ^R w^P x k for a turn by q whose q'' is zero. The zeros erase their terms at
// compile time, where a zero held in a number would be multiplied.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/list.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/rebuild.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/speeds/component_speeds.hpp"
#include "kane/speeds/generalized_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// q_I' is a speed of Sp: q_I'' = 0 at rest
template <class Sp, std::size_t I>
constexpr bool rate_is_speed() {
  if constexpr (std::is_void_v<Sp>)
    return true;
  else if constexpr (Sp::identity)
    return true;
  else
    return []<std::size_t... R>(std::index_sequence<R...>) {
      return (std::is_same_v<row_t<Sp, R>, coordinate<I, 1>> || ...);
    }
  (std::make_index_sequence<Sp::defined>{});
}

template <class Sp, class X>
constexpr auto rest_bias(X x);

// ^R alpha^F at rest, or the node alpha<F> where the speeds do not give it
template <class Sp, class F>
constexpr auto alpha_at_rest() {
  using P = typename F::tree_parent;
  constexpr std::size_t k = [] {
    if constexpr (std::is_void_v<Sp> || std::is_void_v<P>)
      return std::size_t(0);
    else
      return component_speeds<Sp, F>();
  }();
  if constexpr (std::is_void_v<P>)
    return zero_vector{};
  else if constexpr (k != 0) {
    using G = typename component_row<row_t<Sp, k - 1>>::frame;
    if constexpr (std::is_same_v<G, F> || std::is_void_v<typename G::tree_parent>)
      return zero_vector{};
    else
      return derived_cross(omega_of<G>(), omega<F>{});
  } else if constexpr (spin_edge<F>)
    return rest_bias<Sp>(alpha_of<P>()) +
           derived_cross(omega_of<P>(), speed<F::step::speed_index>{} * axis_vector<F, P>());
  else if constexpr (matrix_edge<F>)
    return alpha<F>{};
  else if constexpr (F::step::coordinate_index != 0 && rate_is_speed<Sp, F::step::coordinate_index>())
    return rest_bias<Sp>(alpha_of<P>()) +
           coordinate<F::step::coordinate_index, 1>{} * derived_cross(omega_of<P>(), axis_vector<F>());
  else
    return alpha<F>{};
}

// x at rest: u' and the q'' that are speeds zero, the angular accelerations the speeds give written
// out; any other leaf is the evaluator's number at rest
template <class Sp>
struct bias_rule {
  template <class X>
  static constexpr bool handles =
      coordinate_info<X>::value || speed_info<X>::value || is_v<X, alpha> || is_v<X, angular_acceleration_of>;
  template <class X>
  static constexpr auto apply(X x) {
    if constexpr (coordinate_info<X>::value) {
      if constexpr (X::order == 2 && rate_is_speed<Sp, X::index>())
        return zero_t{};
      else
        return x;
    } else if constexpr (speed_info<X>::value) {
      if constexpr (X::order == 1)
        return zero_t{};
      else
        return x;
    } else if constexpr (is_v<X, alpha>)
      return alpha_at_rest<Sp, typename X::frame>();
    else
      return rest_bias<Sp>(expand(x));
  }
  template <class X>
  static constexpr auto other(X x) {
    return x;
  }
};
template <class Sp, class X>
constexpr auto rest_bias(X x) {
  return rebuild<bias_rule<Sp>>(x);
}

// The terms of a list, each at rest: what motion's pass must compute (evaluation/reads.hpp).
template <class Sp, class... X>
constexpr auto rest_terms(list<X...>)
    -> list<std::remove_cvref_t<decltype(rest_bias<Sp>(std::declval<X>()))>...>;

}  // namespace kane::detail
#pragma GCC diagnostic pop
