// The axes of a frame from its parent's and its edge (outward_pass.hpp): e_Fj = sum_k
// (^P P^F)_jk e_Pk in the root's components, column after column. A turn about a principal axis
// of P by q (sin and cos from the pass's cache) moves two columns; below the root they are the
// elementary rotation itself; Euler parameters and runtime attitudes give ^P P^F from the state.
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/patterned.hpp"
#include "kane/evaluation/edge_structure.hpp"
#include "kane/frames/angle.hpp"
#include "kane/frames/axis.hpp"
#include "kane/frames/orientation.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// cf: F's columns; parent: P's columns (not read for P the root).
template <class F, class S, class Trig, class St>
KANE_ALWAYS_INLINE void edge_columns(S* cf, const S* parent, const Trig& t, const St& st) {
  using matrix3 = Eigen::Matrix<S, 3, 3>;
  using P = typename F::tree_parent;
  constexpr bool below_root = std::is_void_v<typename P::tree_parent>;
  Eigen::Map<matrix3> m(cf);
  if constexpr (euler_edge<F>) {  // the evaluator's Euler parameters are of unit norm
    constexpr auto i = F::step::coordinates;
    matrix3 e;  // (^P P^F)^T
    quaternion_columns(below_root ? cf : e.data(), st.q[i[0] - 1], st.q[i[1] - 1], st.q[i[2] - 1],
                       st.q[i[3] - 1], S(1));
    if constexpr (!below_root) m.noalias() = Eigen::Map<const matrix3>(parent) * e;
  } else if constexpr (matrix_edge<F>) {
    const matrix3 e = F::step::template matrix<S>(t, st);
    if constexpr (below_root)
      m = e.transpose();
    else
      m.noalias() = Eigen::Map<const matrix3>(parent) * e.transpose();
  } else {
    using K = typename F::step::axis;
    constexpr std::size_t q = F::step::coordinate_index;
    constexpr int p = unit_axis<K>::principal;
    S c, s;
    if constexpr (q != 0) {
      c = t.template cos<q>(), s = t.template sin<q>();
    } else {
      using std::cos;
      using std::sin;
      const S a = angle_value<S>(F::step::angle, st);
      c = cos(a), s = sin(a);
    }
    if constexpr (p >= 0) {
      if constexpr (below_root) {  // the parent's axes are the identity
        constexpr int a = (p + 1) % 3, b = (p + 2) % 3;
        for (int k = 0; k < 9; ++k) cf[k] = S(0);
        cf[3 * p + p] = S(1), cf[3 * a + a] = c, cf[3 * a + b] = s, cf[3 * b + a] = -s, cf[3 * b + b] = c;
      } else {
        turn_columns<column_pattern<P>(), p>(cf, parent, c, s);
      }
    } else {
      const matrix3 e = elementary<S, K>(c, s);
      if constexpr (below_root)
        m = e.transpose();
      else
        m.noalias() = Eigen::Map<const matrix3>(parent) * e.transpose();
    }
  }
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
