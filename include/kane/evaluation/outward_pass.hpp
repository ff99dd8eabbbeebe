// The outward pass over a frame tree: for each frame F
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

#include "kane/detail/choices.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/component_rates.hpp"
#include "kane/evaluation/edge_columns.hpp"
#include "kane/evaluation/edge_structure.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/orientation.hpp"
#include "kane/speeds/kinematic_weights.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
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

  struct every_frame {  // every frame's angular acceleration
    static constexpr std::array<bool, size> alpha = every<size>();
  };
  // One pass at the levels asked for, frame after frame; at the acceleration level the
  // frames of Reads::alpha only (by closure index).
  template <stages Levels, class Reads = every_frame, class Rates>
  KANE_ALWAYS_INLINE void pass(const trig_type& t, const Rates& rates) {
    pass_over<Levels, Reads>(closure{}, t, rates);
  }

  // ^R w^F = sum u_k+i-1 g_i (D = 0), ^R alpha^F = sum u'_k+i-1 g_i + ^R w^G x ^R w^F (D = 1); Rest: u' = 0
  template <class F, std::size_t D, bool Rest = false, class Rates>
  KANE_ALWAYS_INLINE v3<scalar> components_value(const Rates& rates) const {
    using G = component_frame_t<closure, F, Rates>;
    v3<scalar> x = component_values<component_speeds_in<closure, F, Rates>(), D>(rates);  // 0 or NaN at rest
    if constexpr (is_edge<G> && !Rest) x = x.x * column<G>(0) + x.y * column<G>(1) + x.z * column<G>(2);
    if constexpr (D == 1 && is_edge<G> && !std::is_same_v<G, F>)
      x = x + cross3(load3(w_[index<G>()].data()), load3(w_[index<F>()].data()));
    return x;
  }
  // element by element (a wide copy of values just written narrowly would stall) and unrolled
  // (g++ 12: after a loop it no longer forwards the pass's stores to the reads that follow)
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

  template <stages Levels, class Reads, class Rates, class... F>
  KANE_ALWAYS_INLINE void pass_over(list<F...>, const trig_type& t, const Rates& rates) {
    // g++ 12: no lambdas, which -O2 left out of line
    (edge<read_only(Levels, Reads::alpha[index<F>()]), F>(t, rates), ...);
  }
  template <stages Levels, class F, class Rates>
  KANE_ALWAYS_INLINE void edge(const trig_type& t, const Rates& rates) {
    constexpr bool velocity = has(Levels, stages::velocity), acceleration = has(Levels, stages::acceleration);
    if constexpr (has(Levels, stages::pose)) pose_edge<F>(t, rates);
    if constexpr (velocity && component_speeds_in<closure, F, Rates>() != 0)
      store3(w_[index<F>()].data(), components_value<F, 0>(rates));
    else if constexpr (velocity)
      velocity_edge<F>(rates);
    if constexpr (has(Levels, stages::nan_acceleration))
      fill_nan(a_[index<F>()]);
    else if constexpr (acceleration && component_speeds_in<closure, F, Rates>() != 0)
      store3(a_[index<F>()].data(), components_value<F, 1, has(Levels, stages::rest)>(rates));
    else if constexpr (acceleration)
      acceleration_edge<F>(rates);
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
      return add_along < axis_pattern<F>(),
             below_root<F>() ? onto::zero : onto::sum > (x, angle_rate_value<F, D>(rates), edge_axis<F>());
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
    if constexpr (is_edge<F> && !spin_edge<F>) {  // a spinning frame's axes stay NaN: axes<F> refuses them
      edge_columns<F>(c_[index<F>()].data(), c_[index<typename F::tree_parent>()].data(), t, rates.state());
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
#pragma GCC diagnostic pop
