// Components of a vector expression in a frame A, node by node (evaluate.hpp computes in the
// root's): unit vectors of A are constants, sums and cross products stay in A, and angular
// velocities and accelerations that the speeds give are read without a rotation. Kane's sums
// take their dot products in each body's frame this way (dynamics/sums.hpp).
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/detail/tree.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/component_rates.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/expressions/direction_cosines.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/speeds/component_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// Where ^R w^F (D = 0) and ^R alpha^F (D = 1) have components in A without a rotation:
// 1 for a frame whose speeds u_k..u_k+2 are them (u or u'; alpha needs G = F), 2 for a frame
// one spin or simple turn about a principal axis below such a frame A (w_P + rate k,
// alpha_P + rate' k + rate w_P x k), 0 elsewhere.
template <class A, class F, class Ev, std::size_t D>
constexpr int known_in() {
  using Sp = typename Ev::speed_set;
  if constexpr (std::is_void_v<Sp> || std::is_void_v<typename F::tree_parent>)
    return 0;
  else if constexpr (component_speeds<Sp, F>() != 0) {
    using G = typename component_row<row_t<Sp, component_speeds<Sp, F>() - 1>>::frame;
    return std::is_same_v<G, A> && (D == 0 || std::is_same_v<G, F>) ? 1 : 0;
  } else if constexpr (std::is_same_v<typename F::tree_parent, A> && !attitude_edge<F> && !euler_edge<F>) {
    if constexpr (unit_axis<typename F::step::axis>::principal >= 0 &&
                  (spin_edge<F> || F::step::coordinate_index != 0))
      return known_in<A, A, Ev, 0>() && known_in<A, A, Ev, D>() ? 2 : 0;
    else
      return 0;
  } else
    return 0;
}
template <class A, class F, std::size_t D, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> rates_in(const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (known_in<A, F, Ev, D>() == 1) {
    return component_values<component_speeds<typename Ev::speed_set, F>(), D>(ev);
  } else {
    constexpr int p = unit_axis<typename F::step::axis>::principal;
    const auto rate = [&](auto d) {
      if constexpr (spin_edge<F>)
        return eval_scalar(speed<F::step::speed_index, decltype(d)::value>{}, ev);
      else
        return ev.template coordinate_value<F::step::coordinate_index, decltype(d)::value + 1>();
    };
    v3<S> out = rates_in<A, A, D>(ev);
    if constexpr (D == 0) {
      (p == 0 ? out.x : p == 1 ? out.y : out.z) += rate(index_c<0>{});
    } else {
      const v3<S> w = rates_in<A, A, 0>(ev);
      const S r = rate(index_c<0>{});
      (p == 0 ? out.x : p == 1 ? out.y : out.z) += rate(index_c<1>{});
      out = out + r * cross3(w, v3<S>{S(p == 0), S(p == 1), S(p == 2)});
    }
    return out;
  }
}

// Components in A, node by node: unit vectors of A are constants, sums and cross products
// stay in A (a cross with constants folds), angular velocities and accelerations that the
// speeds give are read (known_in), the rest is rotated from the root's components.
template <class A, class Ev, class V>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> eval_in(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (std::is_same_v<A, root_of<A>>)
    return eval_vector(v, ev);
  else if constexpr (requires { ev.base(); })  // a plan of common subexpressions (memo.hpp) is in root order
    return eval_in<A>(v, ev.base());
  else if constexpr (is_zero_vector_v<V>)
    return {S(0), S(0), S(0)};
  else if constexpr (is_unit<V>::value) {
    using F = lifted_t<typename V::frame, V::index>;
    if constexpr (std::is_same_v<typename V::frame, A> || std::is_same_v<F, A>)
      return {S(V::index == 1), S(V::index == 2), S(V::index == 3)};
    else if constexpr (std::is_void_v<typename F::tree_parent>) {  // e_Rj in A: row j of A's axes
      const auto* c = ev.template axes<A>().data() + (V::index - 1);
      return {c[0], c[3], c[6]};
    } else
      return in_frame<A>(eval_vector(v, ev), ev);
  } else if constexpr (is_v<V, scaled>)
    return scale_known<zeros_in_v<A, decltype(v.v)>>(eval_scalar(v.s, ev), eval_in<A>(v.v, ev));
  else if constexpr (is_v<V, vsum>)
    return add_known<zeros_in_v<A, decltype(v.l)>, zeros_in_v<A, decltype(v.r)>>(eval_in<A>(v.l, ev),
                                                                                 eval_in<A>(v.r, ev));
  else if constexpr (is_v<V, vdiff>)
    return subtract_known<zeros_in_v<A, decltype(v.l)>, zeros_in_v<A, decltype(v.r)>>(eval_in<A>(v.l, ev),
                                                                                      eval_in<A>(v.r, ev));
  else if constexpr (is_v<V, vneg>)
    return -eval_in<A>(v.v, ev);
  else if constexpr (is_v<V, vcross>)
    return cross_known<zeros_in_v<A, decltype(v.l)>, zeros_in_v<A, decltype(v.r)>>(eval_in<A>(v.l, ev),
                                                                                   eval_in<A>(v.r, ev));
  else if constexpr (Quantity<V>)
    return eval_in<A>(v.v, ev);
  else if constexpr (is_v<V, omega> || is_v<V, alpha>) {
    constexpr std::size_t d = is_v<V, alpha> ? 1 : 0;
    if constexpr (known_in<A, typename V::frame, Ev, d>())
      return rates_in<A, typename V::frame, d>(ev);
    else
      return in_frame<A>(eval_vector(v, ev), ev);
  } else if constexpr (is_v<V, angular_velocity_of> || is_v<V, angular_acceleration_of>)
    return eval_in<A>(expand(v), ev);
  else
    return in_frame<A>(eval_vector(v, ev), ev);
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
