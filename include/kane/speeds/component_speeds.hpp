// Speeds that are the components of an angular velocity: rows u_K..u_K+2 = ^R w^B . g_1..3 of a
// speed set (R the root) make ^R w^B = sum u g_i, so B's partial angular velocities are g_i
// (partial_velocity.hpp) and its w and alpha come from u and u' (evaluation/outward_pass.hpp).
// For B turned by Euler parameters these rows and unit_norm are orthogonal (kinematic equations).
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/tree.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// Speeds u_K..u_K+2 = ^R w^B . f_1..3 with R the root: then ^R w^B = sum_i u_K+i-1 f_i
// identically, and its partial angular velocities are f_1, f_2, f_3 (no W).
template <class T>
struct component_row : std::false_type {};
template <class A, class B, class F, int I>
struct component_row<vdot<angular_velocity_of<A, B>, unit<F, I>>> : std::true_type {
  using observer = A;
  using body = B;
  using frame = F;
  static constexpr int index = I;
};
template <class A, class B, class F, int I>
struct component_row<vdot<unit<F, I>, angular_velocity_of<A, B>>>
    : component_row<vdot<angular_velocity_of<A, B>, unit<F, I>>> {};
template <class Sp, std::size_t K>
using row_t = std::remove_cvref_t<decltype(std::get<K>(Sp::definitions))>;
template <class Sp, class B, std::size_t K, int I>
constexpr bool component_row_of() {
  using T = component_row<row_t<Sp, K + std::size_t(I) - 1>>;
  using First = component_row<row_t<Sp, K>>;
  if constexpr (T::value && First::value) {
    return std::is_same_v<typename T::body, B> && std::is_same_v<typename T::observer, root_of<B>> &&
           std::is_same_v<typename T::frame, typename First::frame> && T::index == I;
  } else
    return false;
}
// K (1-based) with u_K..u_K+2 the components of ^R w^B, or 0.
template <class Sp, class B>
constexpr std::size_t component_speeds() {
  if constexpr (Sp::identity || Sp::defined < 3)
    return 0;
  else
    return []<std::size_t... K>(std::index_sequence<K...>) {
      std::size_t k = 0;
      ((k = k ? k
            : (component_row_of<Sp, B, K, 1>() && component_row_of<Sp, B, K, 2>() &&
               component_row_of<Sp, B, K, 3>())
                ? K + 1
                : 0),
       ...);
      return k;
    }
  (std::make_index_sequence<Sp::defined - 2>{});
}

// The coordinates (q0..q3) of the Euler parameters whose rates row R of Sp holds with
// orthogonal rows: ^R w^B . g_i for B turned by Euler parameters and G = B or B's parent, or
// B's unit_norm row q0 q0' + ... + q3 q3'; zeros otherwise.
template <class T>
struct norm_row {
  static constexpr std::array<std::size_t, 4> coordinates{};
};
template <std::size_t A, std::size_t B, std::size_t C, std::size_t D>
struct norm_row<add<add<add<mul<coordinate<A, 0>, coordinate<A, 1>>, mul<coordinate<B, 0>, coordinate<B, 1>>>,
                        mul<coordinate<C, 0>, coordinate<C, 1>>>,
                    mul<coordinate<D, 0>, coordinate<D, 1>>>> {
  static constexpr std::array<std::size_t, 4> coordinates{A, B, C, D};
};
template <class Sp, std::size_t R>
constexpr std::array<std::size_t, 4> euler_row() {
  using T = row_t<Sp, R>;
  if constexpr (R >= Sp::defined)
    return norm_row<T>::coordinates;
  else if constexpr (component_row<T>::value) {
    using B = typename component_row<T>::body;
    using G = typename component_row<T>::frame;
    if constexpr (euler_edge<B> && (std::is_same_v<G, B> || std::is_same_v<G, typename B::tree_parent>))
      return B::step::coordinates;
    else
      return {};
  } else
    return {};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
