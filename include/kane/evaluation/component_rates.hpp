// Frames whose angular velocity the speeds give (speeds/component_speeds.hpp) at an evaluator's
// state: ^R w^F = sum u_k+i-1 g_i and ^R alpha^F = sum u'_k+i-1 g_i + ^R w^G x ^R w^F.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/speeds/component_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// k when u_k, u_k+1, u_k+2 are the components of ^R w^F in a frame G whose axes an outward pass
// over Closure knows before F's (G = F, an ancestor, or the root); 0: F's rates come from its edge.
template <class Closure, class F, class Rates>
constexpr std::size_t component_speeds_in() {
  using Sp = typename Rates::speed_set;
  if constexpr (std::is_void_v<Sp> || std::is_void_v<typename F::tree_parent>)
    return 0;
  else if constexpr (component_speeds<Sp, F>() == 0)
    return 0;
  else {
    constexpr std::size_t k = component_speeds<Sp, F>();
    using G = typename component_row<row_t<Sp, k - 1>>::frame;
    if constexpr (std::is_void_v<typename G::tree_parent>)
      return k;
    else if constexpr (contains<G, Closure>::value && contains<F, Closure>::value && !spin_edge<G>)
      return index_of<G, Closure>::value <= index_of<F, Closure>::value ? k : 0;
    else
      return 0;
  }
}
template <class Closure, class F, class Rates>
using component_frame_t = typename component_row<
    row_t<typename Rates::speed_set, component_speeds_in<Closure, F, Rates>() - 1>>::frame;

// (u_k, u_k+1, u_k+2) (D = 0) or their derivatives (D = 1); NaN where the kinematic equations
// failed, as for the rates they give (evaluator.hpp).
template <std::size_t K, std::size_t D, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> component_values(const Ev& ev) {
  using S = typename Ev::scalar;
  const auto spoil = nan_unless_rare<S>(ok_of<S>(ev.status()));
  S x = eval_scalar(speed<K, D>{}, ev), y = eval_scalar(speed<K + 1, D>{}, ev),
    z = eval_scalar(speed<K + 2, D>{}, ev);
  spoil(x), spoil(y), spoil(z);
  return {x, y, z};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
