// The terms of Kane's sums (sums.hpp) for numbers: what the sums evaluate of
// each item of a system (partial velocities, accelerations, masses, loads: the
// group whose common subexpressions evaluation/memo.hpp recalls), and the inertia
// dyadic in the root's components.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/list.hpp"
#include "kane/detail/v3.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/tables.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/point.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// I in the root's components: C (I)_F C^T, C the columns e_F1, e_F2, e_F3; the
// components that are zero at compile time skip their products, and the result
// is symmetric by construction (its upper triangle, mirrored).
template <class Cs, std::size_t K>
constexpr auto inertia_column_rows() {  // the j of I_jk not zero at compile time
  struct rows {
    std::array<std::size_t, 3> j{};
    std::size_t n = 0;
  } out;
  [&]<std::size_t... J>(std::index_sequence<J...>) {
    ((!is_zero_v<std::tuple_element_t<sym_index[J][K], Cs>> ? void(out.j[out.n++] = J) : void()), ...);
  }
  (std::make_index_sequence<3>{});
  return out;
}
// I in its own frame's components.
template <class I, class Ev>
Eigen::Matrix<typename Ev::scalar, 3, 3> inertia_in_own(const Ev& ev) {
  using S = typename Ev::scalar;
  using Cs = std::remove_cvref_t<decltype(I::components)>;
  Eigen::Matrix<S, 3, 3> out;
  store_in_blocks<9>(out.data(), [&](auto jk) KANE_ALWAYS_INLINE_LAMBDA {  // symmetric: rows as columns
    constexpr std::size_t k = sym_index[jk / 3][jk % 3];
    return is_zero_v<std::tuple_element_t<k, Cs>> ? S(0) : S(eval_scalar(std::get<k>(I::components), ev));
  });
  return out;
}
// The components of I that are zero at compile time, as entries of its 3 x 3 matrix.
template <class I>
constexpr zero_pattern<3, 3> inertia_zeros() {
  using Cs = std::remove_cvref_t<decltype(I::components)>;
  return [&]<std::size_t... JK>(std::index_sequence<JK...>) {
    return zero_pattern<3, 3>{{is_zero_v<std::tuple_element_t<sym_index[JK / 3][JK % 3], Cs>>...}};
  }
  (std::make_index_sequence<9>{});
}
// I's zero components where the sums take I in A: its own frame's or its lift IL's, none in others
template <class A, class I, class IL>
constexpr zero_pattern<3, 3> inertia_zeros_in() {
  if constexpr (std::is_same_v<A, typename I::frame>)
    return inertia_zeros<I>();
  else if constexpr (std::is_same_v<A, typename IL::frame>)
    return inertia_zeros<IL>();
  else
    return {};
}
// How many unit vectors of frames other than A the vector V holds (each a rotation to A).
template <class A, class V>
constexpr int foreign_units() {
  if constexpr (is_zero_vector_v<V>)
    return 0;
  else if constexpr (is_unit<V>::value)
    return std::is_same_v<typename V::frame, A> ? 0 : 1;
  else if constexpr (is_v<V, scaled> || is_v<V, vneg> || Quantity<V>)
    return foreign_units<A, std::remove_cvref_t<decltype(std::declval<V>().v)>>();
  else if constexpr (is_v<V, vsum> || is_v<V, vdiff> || is_v<V, vcross>)
    return foreign_units<A, std::remove_cvref_t<decltype(std::declval<V>().l)>>() +
           foreign_units<A, std::remove_cvref_t<decltype(std::declval<V>().r)>>();
  else
    return 1;
}
template <class A, class... V>
constexpr int foreign_units(list<V...>) {
  return (0 + ... + foreign_units<A, V>());
}
// Of the frames Fs (the first the root), the one in which the vectors of list L hold the
// fewest foreign unit vectors: the sums take their dot products there.
template <class L, class F, class... Fs>
struct cheapest_frame {
  using type = F;
};
template <class L, class F, class G, class... Fs>
struct cheapest_frame<L, F, G, Fs...> {
  using rest = typename cheapest_frame<L, G, Fs...>::type;
  using type = std::conditional_t<(foreign_units<rest>(L{}) < foreign_units<F>(L{})), rest, F>;
};
template <class I, class Ev>
Eigen::Matrix<typename Ev::scalar, 3, 3> inertia_in_root(const Ev& ev) {
  using S = typename Ev::scalar;
  using Cs = std::remove_cvref_t<decltype(I::components)>;
  std::array<S, 6> v;
  static_for<6>([&](auto k) {
    v[k] = is_zero_v<std::tuple_element_t<k, Cs>> ? S(0) : S(eval_scalar(std::get<k>(I::components), ev));
  });
  Eigen::Matrix<S, 3, 3> out;
  if constexpr (std::is_void_v<typename I::frame::tree_parent>) {
    static_for<9>(
        [&](auto jk) { out(Eigen::Index(jk / 3), Eigen::Index(jk % 3)) = v[sym_index[jk / 3][jk % 3]]; });
  } else {
    const auto c = ev.template axes<typename I::frame>();
    Eigen::Matrix<S, 3, 3> p;  // C I
    static_for<9>([&](auto rk) {
      constexpr std::size_t r = rk / 3, k = rk % 3;
      constexpr auto rows = inertia_column_rows<Cs, k>();
      const auto term = [&](auto t) {
        constexpr std::size_t j = rows.j[t];
        return S(c(Eigen::Index(r), Eigen::Index(j)) * v[sym_index[j][k]]);
      };
      if constexpr (rows.n == 0) {
        p(Eigen::Index(r), Eigen::Index(k)) = S(0);
      } else {
        S sum = term(index_c<0>{});
        static_for<rows.n - 1>([&](auto t) { sum += term(index_c<t + 1>{}); });
        p(Eigen::Index(r), Eigen::Index(k)) = sum;
      }
    });
    static_for<9>([&](auto rs) {
      constexpr std::size_t r = rs / 3, s = rs % 3;
      if constexpr (r <= s) {
        const S x = p(Eigen::Index(r), 0) * c(Eigen::Index(s), 0) +
                    p(Eigen::Index(r), 1) * c(Eigen::Index(s), 1) +
                    p(Eigen::Index(r), 2) * c(Eigen::Index(s), 2);
        out(Eigen::Index(r), Eigen::Index(s)) = x, out(Eigen::Index(s), Eigen::Index(r)) = x;
      }
    });
  }
  return out;
}
// What the equations evaluate of an item X of the system: partial velocities, then
// accelerations, masses, inertias and loads.
template <class Sp, class V, class = std::make_index_sequence<Sp::n>>
struct columns_of;
template <class Sp, class V, std::size_t... C>
struct columns_of<Sp, V, std::index_sequence<C...>> {
  using type = list<std::remove_cvref_t<decltype(column_of<Sp, C + 1>(std::declval<const V&>()))>...>;
};
template <class Sp, class V>
using columns_t = typename columns_of<Sp, V>::type;
template <class R, class Sp, class X>
auto terms_of() {
  if constexpr (is_particle<X> || is_body<X>) {
    using P = typename point_of_mass<X>::type;
    using mass_terms =
        typename concat<columns_t<Sp, decltype(velocity<R, P>())>,
                        list<decltype(acceleration<R, P>()), std::remove_cvref_t<decltype(X::mass)>>>::type;
    if constexpr (is_body<X>) {
      using B = typename X::frame;
      return typename concat<
          mass_terms, columns_t<Sp, decltype(angular_velocity<R, B>())>,
          list<decltype(angular_acceleration<R, B>()), decltype(angular_velocity<R, B>())>>::type{};
    } else
      return mass_terms{};
  } else if constexpr (is_force<X>)
    return typename concat<columns_t<Sp, decltype(velocity<R, typename X::point>())>,
                           list<std::remove_cvref_t<decltype(X::vector)>>>::type{};
  else if constexpr (is_torque<X>)
    return typename concat<columns_t<Sp, decltype(angular_velocity<R, typename X::frame>())>,
                           list<std::remove_cvref_t<decltype(X::vector)>>>::type{};
  else if constexpr (is_gravity<X>)
    return list<std::remove_cvref_t<decltype(X::vector)>>{};
  else
    return list<>{};
}
template <class R, class Sp, class... X>
auto system_terms(list<X...>) {
  return typename concat<decltype(terms_of<R, Sp, X>())...>::type{};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
