// Direction cosines between any two frames of a tree at a state, and
// components re-expressed in another frame.
#pragma once

#include <Eigen/Core>

#include "kane/dcm.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/frame.hpp"
#include "kane/state.hpp"
#include "kane/vec.hpp"

namespace kane {

namespace detail {

template <class A, class B>
struct joined_path : path<A, B> {
  static_assert(path<A, B>::joined,
                "kane: no path of the frame tree joins these two frames (their roots differ); "
                "relate them through a common root frame");
};

template <class Up, class Down>
struct path_coordinates;
template <class... Up, class... Down>
struct path_coordinates<list<Up...>, list<Down...>> {
  static constexpr auto value = [] {
    constexpr std::size_t n = (std::size_t{0} + ... + Up::orientation::coordinates.size()) +
                              (std::size_t{0} + ... + Down::orientation::coordinates.size());
    std::array<std::size_t, n> all{};
    std::size_t k = 0;
    [[maybe_unused]] auto add = [&](const auto& c) {
      for (std::size_t i : c) all[k++] = i;
    };
    (add(Up::orientation::coordinates), ...);
    (add(Down::orientation::coordinates), ...);
    return all;
  }();
};

template <std::size_t N, std::array<std::size_t, N> All, std::size_t... I>
constexpr auto unique_of(std::index_sequence<I...>) {
  return unique_indices<All[I]...>();
}

// A factor of a chain: ^P P^F of the edge above F, transposed when walking up.
template <class F, bool Up>
struct edge {
  template <class S, class Trig>
  static Eigen::Matrix<S, 3, 3> matrix(const Trig& t) {
    if constexpr (Up)
      return F::orientation::template matrix<S>(t).transpose();
    else
      return F::orientation::template matrix<S>(t);
  }
};

// Product of the factors, the first applied first; the identity when empty.
// No factor is multiplied by an identity, so a NaN stays in the entries
// that are computed from it.
template <class S, class Trig>
Eigen::Matrix<S, 3, 3> chain(const Trig&, list<>) {
  return Eigen::Matrix<S, 3, 3>::Identity();
}
template <class S, class Trig, class First, class... Rest>
Eigen::Matrix<S, 3, 3> chain(const Trig& t, list<First, Rest...>) {
  Eigen::Matrix<S, 3, 3> m = First::template matrix<S>(t);
  ((m = Rest::template matrix<S>(t) * m), ...);
  return m;
}

// ^A P^B = E_B ... E_c1 . E_u(k)^T ... E_A^T over the path A -> common -> B.
template <class Up, class Down>
struct factors;
template <class... Up, class... Down>
struct factors<list<Up...>, list<Down...>> {
  using type = list<edge<Up, true>..., edge<Down, false>...>;
};

}  // namespace detail

// ^A P^B at the state st; sin and cos of each coordinate on the path once.
template <Frame A, Frame B, State St>
dcm<A, B, typename St::scalar> direction_cosines(const St& st) {
  using S = typename St::scalar;
  using p = detail::joined_path<A, B>;
  if constexpr (!p::joined) {
    return {};
  } else {
    constexpr auto all = detail::path_coordinates<typename p::up, typename p::down>::value;
    constexpr auto needed = detail::unique_of<all.size(), all>(std::make_index_sequence<all.size()>{});
    const auto t = detail::make_trig<needed>(st);
    return dcm<A, B, S>(
        detail::chain<S>(t, typename detail::factors<typename p::up, typename p::down>::type{}));
  }
}

// ^B p from ^A p at the state st.
template <Frame B, Frame A, State St>
vec<B, typename St::scalar> express(const vec<A, typename St::scalar>& p, const St& st) {
  return direction_cosines<A, B>(st) * p;
}

}  // namespace kane
