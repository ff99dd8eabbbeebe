// Kane's generalized active and inertia forces of a system as expressions
// (type-level, printable with kane/print.hpp, evaluable with kane::evaluate):
//
//   ^N F_r  = sum v_r . R + w_r . T                                generalized_active_force<N, Sys, Sp, r>()
//   ^N F*_r = -sum m a . v_r + (I . alpha + w x I . w) . w_r      generalized_inertia_force<N, Sys, Sp, r>()
//
// v_r, w_r the partial (angular) velocities in N for the speeds Sp; F_r + F*_r = 0
// are Kane's dynamical equations. Numbers at a state come cheaper from
// mass_matrix_and_forcing (one pass, no expression per r); these say what is summed.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>

#include "kane/detail/v3.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/speeds/partial_velocity.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// I . x = sum_j f_j sum_k I_jk (f_k . x), I in F's components
template <class I, class X>
constexpr auto dyadic_dot(X x) {
  using F = typename I::frame;
  constexpr auto c = I::components;
  const auto row = [&]<std::size_t J>(std::integral_constant<std::size_t, J>) {
    return (std::get<sym_index[J - 1][0]>(c) * dot(e<F, 1>, x) +
            std::get<sym_index[J - 1][1]>(c) * dot(e<F, 2>, x) +
            std::get<sym_index[J - 1][2]>(c) * dot(e<F, 3>, x)) *
           e<F, J>;
  };
  using one = std::integral_constant<std::size_t, 1>;
  using two = std::integral_constant<std::size_t, 2>;
  using three = std::integral_constant<std::size_t, 3>;
  return row(one{}) + row(two{}) + row(three{});
}
template <class N, class Sys, class Sp, std::size_t R, class X>
constexpr auto active_term() {
  if constexpr (is_force<X>)
    return dot(partial_velocity<Sp>(velocity<N, typename X::point>(), speed<R>{}), X::vector);
  else if constexpr (is_torque<X>)
    return dot(partial_velocity<Sp>(angular_velocity<N, typename X::frame>(), speed<R>{}), X::vector);
  else if constexpr (is_particle<X> || is_body<X>) {  // the weight m g of each mass
    constexpr auto g = gravity_of(typename Sys::items{});
    return dot(partial_velocity<Sp>(velocity<N, typename point_of_mass<X>::type>(), speed<R>{}), X::mass * g);
  } else
    return constant<0>{};
}
template <class N, class Sp, std::size_t R, class X>
constexpr auto inertia_term() {
  if constexpr (is_particle<X> || is_body<X>) {
    using P = typename point_of_mass<X>::type;
    constexpr auto translation =
        -X::mass * dot(acceleration<N, P>(), partial_velocity<Sp>(velocity<N, P>(), speed<R>{}));
    if constexpr (is_particle<X>)
      return translation;
    else {
      using B = typename X::frame;
      using I = typename X::inertia_type;
      constexpr auto w = angular_velocity<N, B>();
      constexpr auto torque = dyadic_dot<I>(angular_acceleration<N, B>()) + cross(w, dyadic_dot<I>(w));
      return translation - dot(torque, partial_velocity<Sp>(w, speed<R>{}));
    }
  } else
    return constant<0>{};
}
}  // namespace detail

// ^N F_r = sum v_r . R + w_r . T of the system Sys for the speeds Sp
template <Frame N, System Sys, SpeedSet Sp, std::size_t R>
constexpr auto generalized_active_force() {
  return []<class... X>(detail::list<X...>) {
    return (constant<0>{} + ... + detail::active_term<N, Sys, Sp, R, X>());
  }(typename Sys::items{});
}

// ^N F*_r = -sum m a . v_r + (I . alpha + w x I . w) . w_r of Sys for the speeds Sp
template <Frame N, System Sys, SpeedSet Sp, std::size_t R>
constexpr auto generalized_inertia_force() {
  return []<class... X>(detail::list<X...>) {
    return (constant<0>{} + ... + detail::inertia_term<N, Sp, R, X>());
  }(typename Sys::items{});
}

}  // namespace kane
#pragma GCC diagnostic pop
