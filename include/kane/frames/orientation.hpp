// Orientations of a child frame C relative to its parent P, as ^P P^C.
//
// Convention: ^C p = ^P P^C . ^P p, (^P P^C)_ij = e_Ci . e_Pj.
// A simple rotation about the unit axis k (fixed in P and C) by the angle q
// turns P into C in the right-handed sense: ^P P^C = R(k, q)^T with R the
// Rodrigues matrix cos q I + sin q [k]x + (1 - cos q) k k^T. The angle may
// also be an expression of coordinates, parameters and numbers (angle.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/frames/angle.hpp"
#include "kane/frames/axis.hpp"
#include "kane/scalars/coordinate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

// ^P P^C of the simple rotation about K with cos q = c, sin q = s.
template <class S, class K>
Eigen::Matrix<S, 3, 3> elementary(S c, S s) {
  constexpr int principal = unit_axis<K>::principal;
  const S o(0), l(1);
  Eigen::Matrix<S, 3, 3> m;
  if constexpr (principal == 0) {
    m << l, o, o, o, c, s, o, -s, c;
  } else if constexpr (principal == 1) {
    m << c, o, -s, o, l, o, s, o, c;
  } else if constexpr (principal == 2) {
    m << c, s, o, -s, c, o, o, o, l;
  } else {
    constexpr auto k = unit_axis<K>::value;
    const S k1 = static_cast<S>(k[0]), k2 = static_cast<S>(k[1]), k3 = static_cast<S>(k[2]), d = l - c;
    m << c + d * k1 * k1, d * k1 * k2 + s * k3, d * k1 * k3 - s * k2,  //
        d * k2 * k1 - s * k3, c + d * k2 * k2, d * k2 * k3 + s * k1,   //
        d * k3 * k1 + s * k2, d * k3 * k2 - s * k1, c + d * k3 * k3;
  }
  return m;
}

template <int I>
using numbered_axis = direction<I == 1, I == 2, I == 3>;

template <int I, int J, int K>
constexpr bool valid_sequence() {
  return I >= 1 && I <= 3 && J >= 1 && J <= 3 && K >= 1 && K <= 3 && I != J && J != K;
}

// |e|^2 ^P P^C of the Euler parameters e = (a, b, c, d), transposed (^C P^P: its columns are
// c_1, c_2, c_3 in P), column after column into m; k = 1/|e|^2 (1 where e is of unit norm).
template <class S>
KANE_ALWAYS_INLINE void quaternion_columns(S* m, S a, S b, S c, S d, S k) {
  const S aa = a * a, bb = b * b, cc = c * c, dd = d * d, w = 2 * k;
  m[0] = k * (aa + bb - cc - dd), m[1] = w * (b * c + a * d), m[2] = w * (b * d - a * c);
  m[3] = w * (b * c - a * d), m[4] = k * (aa - bb + cc - dd), m[5] = w * (c * d + a * b);
  m[6] = w * (b * d + a * c), m[7] = w * (c * d - a * b), m[8] = k * (aa - bb - cc + dd);
}
// ^P P^C of the Euler parameters (a, b, c, d), divided by their squared norm.
template <class S>
Eigen::Matrix<S, 3, 3> quaternion_matrix(S a, S b, S c, S d) {
  Eigen::Matrix<S, 3, 3> m;
  quaternion_columns(m.data(), a, b, c, d, S(1) / (a * a + b * b + c * c + d * d));
  m.transposeInPlace();
  return m;
}

}  // namespace detail

// C rotated from P about K (components in P, equal in C) by the angle A.
template <Axis K, class A>
struct simple {
  static_assert(Angle<A>,
                "kane: simple<Axis, Angle> turns by a coordinate q_i, a parameter, a constant or "
                "kane::angle<X> with X an expression of coordinates, parameters, numbers and t (no speed)");
  // K, fixed in P and C
  using axis = K;
  // the angle as a scalar expression
  static constexpr auto angle = detail::angle_argument<A>::value;
  // i when the angle is q_i itself (sin and cos cached per state), else 0
  static constexpr std::size_t coordinate_index = detail::bare_coordinate<std::remove_cv_t<decltype(angle)>>;
  // one edge: this rotation
  using steps = detail::list<simple>;
  // ^P P^C
  template <class S, class Trig, class St>
  static Eigen::Matrix<S, 3, 3> matrix(const Trig& tr, const St& st) {
    if constexpr (coordinate_index != 0) {
      return detail::elementary<S, K>(tr.template cos<coordinate_index>(),
                                      tr.template sin<coordinate_index>());
    } else {
      using std::cos;
      using std::sin;
      const S a = detail::angle_value<S>(angle, st);
      return detail::elementary<S, K>(cos(a), sin(a));
    }
  }
};

// Body-fixed I-J-K: about P's axis I by Q1, then the new J by Q2, then the
// newest K by Q3; three simple rotations through two auxiliary frames, so
// ^P P^C = E_K(q3) E_J(q2) E_I(q1).
template <int I, int J, int K, class Q1, class Q2, class Q3>
struct body_fixed {
  static_assert(detail::valid_sequence<I, J, K>(),
                "kane: a rotation sequence takes axes 1, 2, 3 with consecutive axes different "
                "(the twelve sequences 1-2-3 ... 3-2-1 and 1-2-1 ... 3-2-3)");
  // three edges: about I, J and K in turn
  using steps = detail::list<simple<detail::numbered_axis<I>, Q1>, simple<detail::numbered_axis<J>, Q2>,
                             simple<detail::numbered_axis<K>, Q3>>;
};

// Space-fixed I-J-K: about P's fixed axes I by Q1, J by Q2, K by Q3; equal to
// body-fixed K-J-I by (Q3, Q2, Q1). ^P P^C = E_I(q1) E_J(q2) E_K(q3).
template <int I, int J, int K, class Q1, class Q2, class Q3>
struct space_fixed : body_fixed<K, J, I, Q3, Q2, Q1> {};

// Euler parameters (SymPy's 'Quaternion' orientation, scalar part first):
// e = q0 + q1 p1 + q2 p2 + q3 p3 turns P into C, and with n = |e|^2
//   ^P P^C = 1/n [[q0^2 + q1^2 - q2^2 - q3^2, 2 (q1 q2 + q0 q3), 2 (q1 q3 - q0 q2)],
//                 [2 (q1 q2 - q0 q3), q0^2 - q1^2 + q2^2 - q3^2, 2 (q2 q3 + q0 q1)],
//                 [2 (q1 q3 + q0 q2), 2 (q2 q3 - q0 q1), q0^2 - q1^2 - q2^2 + q3^2]].
// One edge of its own (no axis); its angular velocity is in kinematics/derivative_traits.hpp.
template <class... Q>
struct euler_parameters {
  static_assert(sizeof...(Q) == 4 && (Coordinate<Q> && ...),
                "kane: euler_parameters<q0, q1, q2, q3> takes four coordinates, the scalar part first");
  // i of each q_i, the scalar part first
  static constexpr std::array<std::size_t, 4> coordinates = [] {
    if constexpr (sizeof...(Q) == 4 && (Coordinate<Q> && ...))
      return std::array<std::size_t, 4>{Q::index...};
    else
      return std::array<std::size_t, 4>{1, 2, 3, 4};
  }();
  static_assert(coordinates[0] != coordinates[1] && coordinates[0] != coordinates[2] &&
                    coordinates[0] != coordinates[3] && coordinates[1] != coordinates[2] &&
                    coordinates[1] != coordinates[3] && coordinates[2] != coordinates[3],
                "kane: the four Euler parameters are four different coordinates");
  // 0: no sin and cos of a coordinate cached
  static constexpr std::size_t coordinate_index = 0;
  // one edge: the Euler parameters
  using steps = detail::list<euler_parameters>;
  // ^P P^C from q0, q1, q2, q3 of st, divided by |e|^2
  template <class S, class Trig, class St>
  static Eigen::Matrix<S, 3, 3> matrix(const Trig&, const St& st) {
    static_assert(coordinates[0] <= St::nq && coordinates[1] <= St::nq && coordinates[2] <= St::nq &&
                      coordinates[3] <= St::nq,
                  "kane: the Euler parameters use a coordinate beyond the state; declare the state with at "
                  "least that many coordinates");
    return detail::quaternion_matrix(st.q[coordinates[0] - 1], st.q[coordinates[1] - 1],
                                     st.q[coordinates[2] - 1], st.q[coordinates[3] - 1]);
  }
};

// C spins relative to P about K (fixed in both) at the generalized speed U:
// ^P w^C = u k. Its angle is ignorable, no coordinate: of C's axes only k is
// known (a wheel whose rotation angle enters no equation). U is a free speed
// of the speed set (kane::free_speed), read from the state.
template <Axis K, class U>
struct spin {
  static_assert(Speed<U>, "kane: spin<Axis, U> turns at a generalized speed U = kane::speed<r>");
  // K, fixed in P and C
  using axis = K;
  // r of U = u_r
  static constexpr std::size_t speed_index = [] {
    if constexpr (Speed<U>)
      return U::index;
    else
      return std::size_t(1);
  }();
  // 0: no sin and cos of a coordinate cached
  static constexpr std::size_t coordinate_index = 0;
  // one edge: the spin
  using steps = detail::list<spin>;
};

// An attitude supplied at run time (by an estimator, a simulator): ^P P^C read
// from the state's parameters p_K, ... (data of the state, not constants), its
// angular velocity from three free speeds, ^P w^C = u1 c1 + u2 c2 + u3 c3
// (body_rates) or u1 p1 + u2 p2 + u3 p3 (parent_rates). The evaluator checks it
// (evaluation/evaluator.hpp): a rotation within rotation_tolerance, else status
// not_a_rotation.
// An attitude is a rotation when |M M^T - I| <= rotation_tolerance entrywise and
// |det M - 1| <= rotation_tolerance (a matrix, used as it is), or | |q|^2 - 1 | <= rotation_tolerance (a
// quaternion, then used divided by |q|^2): sqrt(epsilon), 1.5e-8 for double, 3.5e-4 for float.
template <class S>
inline constexpr S rotation_tolerance = S(detail::sqrt_newton(double(std::numeric_limits<S>::epsilon())));

// An attitude's source: ^P P^C read from the parameters p_K .. p_K+8, row after row (row i: c_i in P).
template <std::size_t K>
struct rotation_matrix {
  // p_first .. p_first+count-1 hold ^P P^C: first = K, count = 9
  static constexpr std::size_t first = K, count = 9;
};
// An attitude's source: Euler parameters (q0, q1, q2, q3), as euler_parameters, read from p_K .. p_K+3.
template <std::size_t K>
struct unit_quaternion {
  // p_first .. p_first+count-1 hold e: first = K, count = 4
  static constexpr std::size_t first = K, count = 4;
};
// ^P w^C = u1 c1 + u2 c2 + u3 c3: an attitude's angular velocity in the child's axes.
template <class U1, class U2, class U3>
struct body_rates {
  static_assert(Speed<U1> && Speed<U2> && Speed<U3>, "kane: body_rates<u1, u2, u3> takes three speeds");
  // true: u1, u2, u3 along c1, c2, c3
  static constexpr bool in_child = true;
};
// ^P w^C = u1 p1 + u2 p2 + u3 p3: an attitude's angular velocity in the parent's axes.
template <class U1, class U2, class U3>
struct parent_rates {
  static_assert(Speed<U1> && Speed<U2> && Speed<U3>, "kane: parent_rates<u1, u2, u3> takes three speeds");
  // false: u1, u2, u3 along p1, p2, p3
  static constexpr bool in_child = false;
};

namespace detail {
template <class Rates>
struct rate_speeds {
  static constexpr std::array<std::size_t, 3> value{1, 2, 3};
};
template <template <class, class, class> class R, std::size_t I, std::size_t J, std::size_t K>
struct rate_speeds<R<speed<I>, speed<J>, speed<K>>> {
  static constexpr std::array<std::size_t, 3> value{I, J, K};
};
}  // namespace detail

// An orientation read from the state (Source) that turns at three free speeds (Rates).
template <class Source, class Rates>
struct attitude {
  static_assert(
      requires { Source::first; },
      "kane: attitude<Source, Rates> reads kane::rotation_matrix<K> or kane::unit_quaternion<K>");
  static_assert(
      requires { Rates::in_child; },
      "kane: attitude<Source, Rates> turns at kane::body_rates<...> or kane::parent_rates<...>");
  // where ^P P^C is read from
  using source = Source;
  // r of the speeds u_r of Rates
  static constexpr std::array<std::size_t, 3> rate_speeds = detail::rate_speeds<Rates>::value;
  // the rates are along the child's axes
  static constexpr bool body_rates = Rates::in_child;
  static_assert(rate_speeds[0] != rate_speeds[1] && rate_speeds[0] != rate_speeds[2] &&
                    rate_speeds[1] != rate_speeds[2],
                "kane: the three rates of an attitude are three different speeds");
  // 0: no sin and cos of a coordinate cached
  static constexpr std::size_t coordinate_index = 0;
  // one edge: the attitude
  using steps = detail::list<attitude>;
  // The attitude of st is a rotation (within rotation_tolerance).
  template <class St>
  static bool rotation(const St& st) {
    using S = typename St::scalar;
    constexpr std::size_t k = Source::first - 1;
    const S tol = rotation_tolerance<S>;
    if constexpr (Source::count == 4) {
      const S n = st.p[k] * st.p[k] + st.p[k + 1] * st.p[k + 1] + st.p[k + 2] * st.p[k + 2] +
                  st.p[k + 3] * st.p[k + 3];
      return n - S(1) <= tol && S(1) - n <= tol;  // false for NaN
    } else {
      const Eigen::Matrix<S, 3, 3> m = matrix<S>(0, st);
      const S d = m.determinant() - S(1);
      return ((m * m.transpose() - Eigen::Matrix<S, 3, 3>::Identity()).cwiseAbs().array() <= tol).all() &&
             d <= tol && -d <= tol;
    }
  }
  // ^P P^C from the parameters of st (a quaternion divided by |q|^2)
  template <class S, class Trig, class St>
  static Eigen::Matrix<S, 3, 3> matrix(const Trig&, const St& st) {
    constexpr std::size_t k = Source::first - 1;
    static_assert(Source::first + Source::count - 1 <= St::np,
                  "kane: the attitude is read from parameters beyond the state; declare the state with "
                  "enough parameters");
    if constexpr (Source::count == 4)
      return detail::quaternion_matrix(st.p[k], st.p[k + 1], st.p[k + 2], st.p[k + 3]);
    else
      return Eigen::Map<const Eigen::Matrix<S, 3, 3, Eigen::RowMajor>>(st.p.data() + k);
  }
};

// An orientation is a list of edges: simple rotations, or one edge of Euler parameters.
template <class O>
concept Orientation = requires {
  typename O::steps;
}
&&detail::size<typename O::steps>::value >= 1;

}  // namespace kane
#pragma GCC diagnostic pop
