// Which speeds the recursive passes take (joint_form.hpp), decided at compile time: u_r = q_c'
// for each joint, and at most one free joint, a child B of the root R on Euler parameters whose
// origin is at q_P r1 + q_P+1 r2 + q_P+2 r3 (position_coordinates<R, P>), with
//   u_1..u_3 = ^R w^B . b_i (body rates),   u_4..u_6 = q_P', q_P+1', q_P+2',
// then q' of the joints and unit_norm<B> (free_body_speeds<R, B, P> followed by the joints' q').
// The free joint's partial velocities are screws about its origin: (b_i, 0) and (0, r_i).
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "kane/detail/list.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/speeds/generalized_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// q_C of q_C' (0 for anything else)
template <class T>
inline constexpr std::size_t rate_of = 0;
template <std::size_t C>
inline constexpr std::size_t rate_of<coordinate<C, 1>> = C;

// A vector q_P f1 + q_P+1 f2 + q_P+2 f3 (position_coordinates<F, P>): F and P (0 for any other vector)
template <class V>
struct translation {
  using frame = void;
  static constexpr std::size_t coordinate = 0;
};
template <std::size_t P, std::size_t P1, std::size_t P2, class F>
struct translation<vsum<vsum<scaled<coordinate<P>, unit<F, 1>>, scaled<coordinate<P1>, unit<F, 2>>>,
                        scaled<coordinate<P2>, unit<F, 3>>>> {
  using frame = F;
  static constexpr std::size_t coordinate = P1 == P + 1 && P2 == P + 2 ? P : 0;
};

template <std::size_t NQ>
struct speed_layout {
  bool holds = false;
  int free = -1;               // the free frame's index in the frame list (-1: none)
  std::size_t position = 0;    // P of its origin's coordinates
  std::array<int, NQ> rate{};  // r (from 0) of u_r = q_c', at c - 1 (-1: none, -2: the free joint's)
};

// u_1..u_6 and the last row of a free joint of B below R
template <class R, class B, class... U>
constexpr std::size_t free_rows() {
  using T = std::tuple<U...>;
  constexpr std::size_t n = sizeof...(U);
  if constexpr (!euler_edge<B> || n < 7)
    return 0;
  else {
    constexpr auto w = angular_velocity<R, B>();
    constexpr std::size_t p = rate_of<std::tuple_element_t<3, T>>;
    const bool ok = std::is_same_v<std::tuple_element_t<0, T>, std::remove_cv_t<decltype(dot(w, e<B, 1>))>> &&
                    std::is_same_v<std::tuple_element_t<1, T>, std::remove_cv_t<decltype(dot(w, e<B, 2>))>> &&
                    std::is_same_v<std::tuple_element_t<2, T>, std::remove_cv_t<decltype(dot(w, e<B, 3>))>> &&
                    p != 0 && rate_of<std::tuple_element_t<4, T>> == p + 1 &&
                    rate_of<std::tuple_element_t<5, T>> == p + 2 &&
                    std::is_same_v<std::tuple_element_t<n - 1, T>, std::remove_cv_t<decltype(unit_norm<B>)>>;
    return ok ? p : 0;
  }
}

template <class Sp, class R, class FL, std::size_t NQ>
struct layout_of {
  static constexpr speed_layout<NQ> value{};
};
template <std::size_t N, class R, class FL, std::size_t NQ>
struct layout_of<qdot_speeds<N>, R, FL, NQ> {
  static constexpr auto value = [] {
    speed_layout<NQ> out;
    out.holds = N == NQ;
    for (std::size_t k = 0; k < NQ; ++k) out.rate[k] = int(k);
    return out;
  }();
};
template <auto... U, class R, class... F, std::size_t NQ>
struct layout_of<speeds<U...>, R, list<F...>, NQ> {
  static constexpr auto value = [] {
    speed_layout<NQ> out;
    using Sp = speeds<U...>;
    if constexpr (Sp::free == 0 && Sp::rows == NQ) {
      constexpr std::array<std::size_t, sizeof...(U)> rates{rate_of<std::remove_cv_t<decltype(U)>>...};
      // a free joint: the first child of R on Euler parameters whose speeds match
      constexpr std::array<std::size_t, sizeof...(F)> free{[] {
        if constexpr (std::is_same_v<typename F::tree_parent, R>)
          return free_rows<R, F, std::remove_cv_t<decltype(U)>...>();
        else
          return std::size_t(0);
      }()...};
      std::size_t first = 0;  // the first speed that is a joint's q'
      for (std::size_t f = 0; f < free.size() && out.free < 0; ++f)
        if (free[f] != 0) out.free = int(f), out.position = free[f], first = 6;
      if (Sp::rows != Sp::n + (out.free >= 0 ? 1 : 0)) return speed_layout<NQ>{};
      for (auto& r : out.rate) r = -1;
      if (out.free >= 0)
        for (std::size_t k = 0; k < 3; ++k) out.rate[out.position - 1 + k] = -2;
      bool ok = true;
      for (std::size_t r = first; r < Sp::n; ++r) {
        const std::size_t j = rates[r];
        ok = ok && j >= 1 && j <= NQ && out.rate[j - 1] == -1;
        if (ok) out.rate[j - 1] = int(r);
      }
      out.holds = ok;
    }
    return out;
  }();
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
