// Direction cosines between any two frames of a tree at a state, and
// components re-expressed in another frame.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "kane/detail/choices.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/frames/dcm.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/state.hpp"
#include "kane/frames/vec.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

// The coordinates of the edges on a path, each once.
template <class Up, class Down>
struct path_coordinates;
template <class... Up, class... Down>
struct path_coordinates<list<Up...>, list<Down...>> {
  static constexpr auto value =
      coordinate_indices<Up::step::coordinate_index..., Down::step::coordinate_index...>();
};

// A factor of a chain: ^P P^F of the edge above F, transposed when walking up.
template <class F, walk Way>
struct edge {
  template <class S, class Trig, class St>
  static Eigen::Matrix<S, 3, 3> matrix(const Trig& t, const St& st) {
    static_assert(check<!requires { F::step::speed_index; },
                        error::a_spinning_frame_has_no_known_axes_but_its_spin_axis<F>>);
    if constexpr (requires { F::step::speed_index; }) {
      return Eigen::Matrix<S, 3, 3>::Identity();
    } else {
      if constexpr (requires { F::step::rate_speeds; })  // an attitude: NaN unless a rotation
        if (!F::step::rotation(st))
          return Eigen::Matrix<S, 3, 3>::Constant(std::numeric_limits<S>::quiet_NaN());
      const Eigen::Matrix<S, 3, 3> m = F::step::template matrix<S>(t, st);
      if constexpr (Way == walk::up)
        return m.transpose();
      else
        return m;
    }
  }
};

// Product of the factors, the first applied first; the identity when empty.
// No factor is multiplied by an identity, so a NaN stays in the entries
// that are computed from it.
template <class S, class Trig, class St>
Eigen::Matrix<S, 3, 3> chain(const Trig&, const St&, list<>) {
  return Eigen::Matrix<S, 3, 3>::Identity();
}
template <class S, class Trig, class St, class First, class... Rest>
Eigen::Matrix<S, 3, 3> chain(const Trig& t, const St& st, list<First, Rest...>) {
  Eigen::Matrix<S, 3, 3> m = First::template matrix<S>(t, st);
  ((m = Rest::template matrix<S>(t, st) * m), ...);
  return m;
}

// ^A P^B = E_B ... E_c1 . E_u(k)^T ... E_A^T over the path A -> common -> B.
template <class Up, class Down>
struct factors;
template <class... Up, class... Down>
struct factors<list<Up...>, list<Down...>> {
  using type = list<edge<Up, walk::up>..., edge<Down, walk::down>...>;
};

}  // namespace detail

// ^A P^B at the state st; sin and cos of each coordinate on the path once
// (and of each angle that is not a bare coordinate). All NaN if an attitude on
// the path is not a rotation within rotation_tolerance (an evaluator's not_a_rotation).
template <Frame A, Frame B, State St>
dcm<A, B, typename St::scalar> direction_cosines(const St& st) {
  using S = typename St::scalar;
  using p = detail::joined_path<A, B>;
  if constexpr (!p::joined) {
    return {};
  } else {
    constexpr auto needed = detail::path_coordinates<typename p::up, typename p::down>::value;
    const auto tr = detail::make_trig<needed>(st);
    return dcm<A, B, S>(
        detail::chain<S>(tr, st, typename detail::factors<typename p::up, typename p::down>::type{}));
  }
}

// ^B p from ^A p at the state st.
template <Frame B, Frame A, State St>
vec<B, typename St::scalar> express(const vec<A, typename St::scalar>& p, const St& st) {
  return direction_cosines<A, B>(st) * p;
}

}  // namespace kane
#pragma GCC diagnostic pop
