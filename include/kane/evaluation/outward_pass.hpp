// The outward pass over a frame tree (seed eq. 5, 8-10, 13): for each frame F
// of the closure (ancestors first) and its root R, the columns e_F1, e_F2,
// e_F3, ^R w^F and ^R alpha^F in R's components. For an edge P -> F that
// turns about k by q: e_Fi = R(k, q) e_Pi, ^R w^F = ^R w^P + q' k,
// ^R alpha^F = ^R alpha^P + q'' k + q' ^R w^P x k; for an angle theta
// (frames/angle.hpp), theta, theta' and theta'' in place of q, q', q''. sin and
// cos of each coordinate once per state; q' and q'' come from the caller (Rates).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/list.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/edge_structure.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/orientation.hpp"
#include "kane/speeds/generalized_speeds.hpp"

namespace kane {

template <class... F>
struct frames {};

// What the outward pass computes: orientations, + angular velocities, + angular accelerations.
enum class level { pose, velocity, acceleration };

namespace detail {

template <class S, class Closure, level Level>
class outward_pass {
 public:
  using scalar = S;
  using closure = Closure;
  using root = typename at<closure, 0>::type;
  static constexpr std::size_t size = detail::size<closure>::value;
  using matrix3 = Eigen::Matrix<scalar, 3, 3>;

  // Columns e_F1, e_F2, e_F3 in the root's components: (^R P^F)^T.
  template <class F>
  Eigen::Map<const matrix3> axes() const {
    static_assert(check<!spin_edge<F>, error::a_spinning_frame_has_no_known_axes_but_its_spin_axis<F>>);
    return Eigen::Map<const matrix3>(c_[index<F>()].data());
  }
  // ^R w^F and ^R alpha^F as values, for F held or one edge below a held frame
  // (from the parent's and the edge's rates: F's own axes are not needed).
  template <class F, class Rates>
  KANE_ALWAYS_INLINE v3<scalar> omega_value(const Rates& rates) const {
    static_assert(
        Level >= level::velocity,
        "kane: this evaluator computes no angular velocities; declare it with level::velocity or higher");
    if constexpr (contains<F, closure>::value || !edge_below_held<F>())
      return load3(w_[index<F>()].data());
    else
      return turned<F, 1>(load3(w_[index<typename F::tree_parent>()].data()), rates);
  }
  template <class F, class Rates>
  KANE_ALWAYS_INLINE v3<scalar> alpha_value(const Rates& rates) const {
    static_assert(
        Level >= level::acceleration,
        "kane: this evaluator computes no angular accelerations; declare it with level::acceleration");
    if constexpr (contains<F, closure>::value || !edge_below_held<F>())
      return load3(a_[index<F>()].data());
    else
      return alpha_below<F>(rates);
  }

 protected:
  static constexpr auto cached = step_coordinates<closure>::value;
  using trig_type = trig<scalar, cached>;

  KANE_ALWAYS_INLINE outward_pass() {  // NaN until the first update; the pass writes all but the roots
    fill_nan(trig_.s), fill_nan(trig_.c), fill_nan(c_), fill_nan(w_), fill_nan(a_), init_roots(closure{});
  }

  // Every frame's angular acceleration.
  static constexpr std::array<bool, size> all_frames = [] {
    std::array<bool, size> a{};
    a.fill(true);
    return a;
  }();
  struct every_frame {
    static constexpr std::array<bool, size> alpha = all_frames;
  };
  // One pass at the levels asked for, frame after frame; at the acceleration level the
  // frames of Reads::alpha only (by closure index).
  template <bool Pose, bool Velocity, bool Acceleration, class Reads = every_frame, class Rates>
  KANE_ALWAYS_INLINE void pass(const trig_type& t, const Rates& rates) {
    pass_over<Pose, Velocity, Acceleration, Reads>(closure{}, t, rates);
  }

 public:
  // k when the speeds u_k, u_k+1, u_k+2 are the components of ^R w^F in a frame G whose axes
  // are known before F's (G = F, an ancestor, or the root): then ^R w^F = sum u g_i, and
  // ^R alpha^F = sum u' g_i + ^R w^G x ^R w^F. 0: F's rates come from its edge.
  template <class F, class Rates>
  static constexpr std::size_t component_speeds_of() {
    using Sp = typename Rates::speed_set;
    if constexpr (std::is_void_v<Sp> || !is_edge<F>)
      return 0;
    else if constexpr (component_speeds<Sp, F>() == 0)
      return 0;
    else {
      constexpr std::size_t k = component_speeds<Sp, F>();
      using G = typename component_row<row_t<Sp, k - 1>>::frame;
      if constexpr (!is_edge<G>)
        return k;
      else if constexpr (contains<G, closure>::value && !spin_edge<G>)
        return index<G>() <= index<F>() ? k : 0;
      else
        return 0;
    }
  }

 protected:
  template <class F, class Rates>
  using component_frame =
      typename component_row<row_t<typename Rates::speed_set, component_speeds_of<F, Rates>() - 1>>::frame;
  // sum x_i g_i, x_i = u_k+i-1 (D = 0) or u'_k+i-1 (D = 1)
  template <class F, std::size_t D, class Rates>
  KANE_ALWAYS_INLINE v3<scalar> components_value(const Rates& rates) const {
    constexpr std::size_t k = component_speeds_of<F, Rates>();
    using G = component_frame<F, Rates>;
    // NaN where the kinematic equations failed, as for the rates they give (evaluator.hpp)
    const auto spoil = nan_unless<scalar>(rates.status() == solve_status::ok);
    scalar x = eval_scalar(speed<k, D>{}, rates), y = eval_scalar(speed<k + 1, D>{}, rates),
           z = eval_scalar(speed<k + 2, D>{}, rates);
    spoil(x), spoil(y), spoil(z);
    if constexpr (!is_edge<G>)
      return {x, y, z};
    else
      return x * column<G>(0) + y * column<G>(1) + z * column<G>(2);
  }
  // element by element (a wide copy of values just written narrowly would stall) and unrolled
  // (after a loop g++ no longer forwards the pass's stores to the reads that follow)
  KANE_ALWAYS_INLINE void store_trig(const trig_type& t) {
    detail::static_for<trig_type::size>([&](auto k) { trig_.s[k] = t.s[k], trig_.c[k] = t.c[k]; });
  }
  const trig_type& cached_trig() const { return trig_; }

  template <class F>
  static constexpr std::size_t index() {
    static_assert(detail::check<contains<F, closure>::value,
                                error::evaluator_does_not_hold_the_frame_add_it_to_frames<F>>);
    if constexpr (contains<F, closure>::value)
      return index_of<F, closure>::value;
    else
      return 0;
  }

  template <class F>
  static constexpr bool edge_below_held() {
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return false;
    else if constexpr (matrix_edge<F>)
      return false;  // its rates may be in F's axes
    else
      return contains<typename F::tree_parent, closure>::value;
  }

  template <class F>
  static constexpr bool is_edge = !std::is_void_v<typename F::tree_parent>;

  template <class... F>
  KANE_ALWAYS_INLINE void init_roots(list<F...>) {
    (
        [&] {
          if constexpr (!is_edge<F>)
            c_[index<F>()] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, w_[index<F>()] = {}, a_[index<F>()] = {};
        }(),
        ...);
  }

  template <bool Pose, bool Velocity, bool Acceleration, class Reads, class Rates, class... F>
  KANE_ALWAYS_INLINE void pass_over(list<F...>, const trig_type& t, const Rates& rates) {
    // no lambdas: g++ -O2 left them out of line
    (edge < Pose, Velocity, Acceleration && Reads::alpha[index<F>()], F,
     Acceleration && !Reads::alpha[index<F>()] > (t, rates), ...);
  }
  template <bool Pose, bool Velocity, bool Acceleration, class F, bool Skipped = false, class Rates>
  KANE_ALWAYS_INLINE void edge(const trig_type& t, const Rates& rates) {
    if constexpr (Pose) pose_edge<F>(t, rates);
    if constexpr (Velocity) {
      if constexpr (component_speeds_of<F, Rates>() != 0)
        store3(w_[index<F>()].data(), components_value<F, 0>(rates));
      else
        velocity_edge<F>(rates);
    }
    if constexpr (Skipped) {
      a_[index<F>()].fill(std::numeric_limits<scalar>::quiet_NaN());
    } else if constexpr (Acceleration) {
      if constexpr (component_speeds_of<F, Rates>() != 0) {
        using G = component_frame<F, Rates>;
        vec3 a = components_value<F, 1>(rates);
        if constexpr (is_edge<G> && !std::is_same_v<G, F>)
          a = a + cross3(load3(w_[index<G>()].data()), load3(w_[index<F>()].data()));
        store3(a_[index<F>()].data(), a);
      } else
        acceleration_edge<F>(rates);
    }
  }

  using vec3 = v3<scalar>;
  template <class F>
  KANE_ALWAYS_INLINE vec3 column(int j) const {
    static_assert(check<!spin_edge<F>, error::a_spinning_frame_has_no_known_axes_but_its_spin_axis<F>>);
    return load3(c_[index<F>()].data() + 3 * j);
  }

  // The axis k of the edge above F, in the root's components (fixed in both frames).
  template <class F>
  KANE_ALWAYS_INLINE vec3 edge_axis() const {
    using K = typename F::step::axis;
    using P = typename F::tree_parent;
    constexpr int p = unit_axis<K>::principal;
    if constexpr (p >= 0 && !is_edge<P>) {  // a root's axis: constant
      return {scalar(p == 0), scalar(p == 1), scalar(p == 2)};
    } else if constexpr (p >= 0) {
      return column<P>(p);  // the parent's: known before F's own axes
    } else {                // k has the same components in P and F
      constexpr auto k = unit_axis<K>::value;
      if constexpr (!is_edge<P>)
        return {scalar(k[0]), scalar(k[1]), scalar(k[2])};
      else
        return scalar(k[0]) * column<P>(0) + scalar(k[1]) * column<P>(1) + scalar(k[2]) * column<P>(2);
    }
  }

  template <class F, std::size_t D, class Rates>
  KANE_ALWAYS_INLINE scalar angle_rate_value(const Rates& rates) const {
    if constexpr (F::step::coordinate_index != 0)
      return rates.template coordinate_value<F::step::coordinate_index, D>();
    else
      return eval_scalar(angle_rate<F, D>(), rates);
  }
  // x + theta^(D) k (below the root, whose w and alpha are zero: theta^(D) k)
  template <class F, std::size_t D, class Rates>
  KANE_ALWAYS_INLINE vec3 turned(const vec3& x, const Rates& rates) const {
    if constexpr (!turns<F, D> && below_root<F>())
      return {scalar(0), scalar(0), scalar(0)};
    else if constexpr (!turns<F, D>)
      return x;
    else if constexpr (below_root<F>() || per_component<scalar>(axis_pattern<F>()))
      return add_along<axis_pattern<F>(), below_root<F>()>(x, angle_rate_value<F, D>(rates), edge_axis<F>());
    else
      return x + angle_rate_value<F, D>(rates) * edge_axis<F>();
  }
  // w x k (k = edge_axis)
  template <class F>
  KANE_ALWAYS_INLINE vec3 cross_axis(const vec3& w) const {
    if constexpr (per_component<scalar>(axis_pattern<F>()))
      return cross_along<axis_pattern<F>()>(w, edge_axis<F>());
    else
      return cross3(w, edge_axis<F>());
  }
  // ^R alpha^F = ^R alpha^P + theta'' k + theta' ^R w^P x k
  template <class F, class Rates>
  KANE_ALWAYS_INLINE vec3 alpha_below(const Rates& rates) const {
    constexpr std::size_t ip = index<typename F::tree_parent>();
    const vec3 ap = load3(a_[ip].data());
    if constexpr (below_root<F>())
      return turned<F, 2>(ap, rates);
    else if constexpr (turns<F, 1>)
      return turned<F, 2>(ap, rates) + angle_rate_value<F, 1>(rates) * cross_axis<F>(load3(w_[ip].data()));
    else
      return ap;
  }

  // ^P w^F = sum_i w_i k_i (D = 0) and its F-derivative sum_i w_i' k_i (D = 1) for an edge
  // with no axis: Euler parameters (k_i = e_Fi), an attitude (body rates e_Fi or parent rates e_Pi).
  template <class F, std::size_t D, class Rates>
  KANE_ALWAYS_INLINE vec3 matrix_edge_part(const Rates& rates) const {
    const auto value = [&](auto x) {
      if constexpr (D == 0)
        return eval_scalar(x, rates);
      else
        return eval_scalar(ddt(x), rates);
    };
    if constexpr (attitude_edge<F>) {
      constexpr auto s = F::step::rate_speeds;
      using K = std::conditional_t<F::step::body_rates, F, typename F::tree_parent>;
      return value(speed<s[0]>{}) * column<K>(0) + value(speed<s[1]>{}) * column<K>(1) +
             value(speed<s[2]>{}) * column<K>(2);
    } else {
      constexpr auto w = quaternion_rates<F>();
      return value(std::get<0>(w)) * column<F>(0) + value(std::get<1>(w)) * column<F>(1) +
             value(std::get<2>(w)) * column<F>(2);
    }
  }

  template <class F, class Rates>
  KANE_ALWAYS_INLINE void pose_edge(const trig_type& t, const Rates& rates) {
    if constexpr (spin_edge<F>) {
      // axes unknown: they stay NaN, and no expression can read them (axes<F>)
    } else if constexpr (is_edge<F> && matrix_edge<F>) {
      const matrix3 e = F::step::template matrix<scalar>(t, rates.state());
      Eigen::Map<matrix3> m(c_[index<F>()].data());
      if constexpr (!is_edge<typename F::tree_parent>)
        m = e.transpose();
      else
        m.noalias() = axes<typename F::tree_parent>() * e.transpose();
    } else if constexpr (is_edge<F>) {
      using P = typename F::tree_parent;
      using K = typename F::step::axis;
      constexpr std::size_t q = F::step::coordinate_index;
      constexpr int p = unit_axis<K>::principal;
      scalar c, s;
      if constexpr (q != 0) {
        c = t.template cos<q>(), s = t.template sin<q>();
      } else {
        using std::cos;
        using std::sin;
        const scalar a = angle_value<scalar>(F::step::angle, rates.state());
        c = cos(a), s = sin(a);
      }
      scalar* cf = c_[index<F>()].data();
      if constexpr (p >= 0 && !is_edge<P>) {  // the parent's axes are the identity
        constexpr int a = (p + 1) % 3, b = (p + 2) % 3;
        c_[index<F>()] = {};
        cf[3 * p + p] = scalar(1), cf[3 * a + a] = c, cf[3 * a + b] = s, cf[3 * b + a] = -s,
                   cf[3 * b + b] = c;
      } else if constexpr (p >= 0) {
        turn_columns<column_pattern<P>(), p>(cf, axes<P>().data(), c, s);
      } else {  // e_Fj = sum_k (^P P^F)_jk e_Pk
        const matrix3 e = elementary<scalar, K>(c, s);
        Eigen::Map<matrix3> m(cf);
        if constexpr (!is_edge<P>)
          m = e.transpose();
        else
          m.noalias() = axes<P>() * e.transpose();
      }
    }
  }

  template <class F, class Rates>
  KANE_ALWAYS_INLINE void velocity_edge(const Rates& rates) {
    if constexpr (matrix_edge<F> && below_root<F>())
      store3(w_[index<F>()].data(), matrix_edge_part<F, 0>(rates));
    else if constexpr (is_edge<F> && matrix_edge<F>)
      store3(w_[index<F>()].data(),
             load3(w_[index<typename F::tree_parent>()].data()) + matrix_edge_part<F, 0>(rates));
    else if constexpr (is_edge<F>)
      store3(w_[index<F>()].data(), turned<F, 1>(load3(w_[index<typename F::tree_parent>()].data()), rates));
  }

  // ^R alpha^F = ^R alpha^P + ^F d(^P w^F)/dt + ^R w^P x ^P w^F
  template <class F, class Rates>
  KANE_ALWAYS_INLINE void acceleration_edge(const Rates& rates) {
    if constexpr (matrix_edge<F> && below_root<F>()) {
      store3(a_[index<F>()].data(), matrix_edge_part<F, 1>(rates));
    } else if constexpr (is_edge<F> && matrix_edge<F>) {
      constexpr std::size_t ip = index<typename F::tree_parent>();
      const vec3 wp = load3(w_[ip].data()), we = load3(w_[index<F>()].data()) - wp;
      store3(a_[index<F>()].data(), load3(a_[ip].data()) + matrix_edge_part<F, 1>(rates) + cross3(wp, we));
    } else if constexpr (is_edge<F>)
      store3(a_[index<F>()].data(), alpha_below<F>(rates));
  }

  trig_type trig_;
  std::array<std::array<scalar, 9>, size> c_;  // e_F1, e_F2, e_F3 in R, column after column
  std::array<std::array<scalar, 3>, size> w_, a_;
};

}  // namespace detail
}  // namespace kane
