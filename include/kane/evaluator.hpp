// The evaluator: one outward pass over the frame tree per state, then any
// number of expressions evaluated from its cache.
//
//   kane::evaluator<State, kane::frames<C, E>> ev;  // C, E and their ancestors
//   ev.update(s);                                    // sin/cos once, then per frame
//   kane::vec<N> v = kane::express<N>(expr, ev);     // ^N components of expr
//
// For each frame F (root R) the pass stores, in R's components, the columns
// e_F1, e_F2, e_F3, ^R w^F and ^R alpha^F. For an edge P -> F that turns about
// k by q: e_Fi = R(k, q) e_Pi, ^R w^F = ^R w^P + q' k,
// ^R alpha^F = ^R alpha^P + q'' k + q' ^R w^P x k.
// update(s) keeps a pointer to s: s must outlive the evaluations that follow.
// Evaluating allocates nothing and calls no sin or cos of a frame coordinate.
#pragma once

#include <array>
#include <cmath>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kane/angular_velocity.hpp"
#include "kane/derivative.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/expr.hpp"
#include "kane/state.hpp"
#include "kane/vec.hpp"
#include "kane/vector.hpp"

namespace kane {

template <class... F>
struct frames {};

// What the outward pass computes: orientations, + angular velocities, + angular accelerations.
enum class level { pose, velocity, acceleration };

namespace detail {
template <class L>
struct closure_of;
template <class... F>
struct closure_of<frames<F...>> : closure<F...> {};

template <class L>
struct step_coordinates;
template <class... F>
struct step_coordinates<list<F...>> {
  template <class X>
  static constexpr std::size_t index() {
    if constexpr (std::is_void_v<typename X::tree_parent>)
      return 0;
    else
      return X::step::coordinate::index;
  }
  static constexpr auto value = [] {
    constexpr auto all = unique_indices<index<F>()...>();
    // drop the 0 that stands for roots
    constexpr std::size_t n = all.size() > 0 && all[0] == 0 ? all.size() - 1 : all.size();
    std::array<std::size_t, n> out{};
    for (std::size_t i = 0; i < n; ++i) out[i] = all[all.size() - n + i];
    return out;
  }();
};
}  // namespace detail

template <State St, class Frames, level Level = level::acceleration>
class evaluator;

template <State St, Frame... Fs, level Level>
class evaluator<St, frames<Fs...>, Level> {
 public:
  using state_type = St;
  using scalar = typename St::scalar;
  using closure = typename detail::closure<Fs...>::type;
  static constexpr level computed = Level;
  static constexpr std::size_t size = detail::size<closure>::value;
  using matrix3 = Eigen::Matrix<scalar, 3, 3>;
  using vector3 = Eigen::Matrix<scalar, 3, 1>;

  evaluator() {
    for (auto& c : c_) c.setIdentity();
    for (auto& w : w_) w.setZero();
    for (auto& a : a_) a.setZero();
  }

  // The outward pass at s; s must outlive the evaluations that follow.
  void update(const St& s) {
    st_ = &s;
    trig_ = detail::make_trig<cached>(s);
    pass(closure{});
  }

  const St& state() const { return *st_; }

  template <class F>
  static constexpr bool holds = detail::contains<F, closure>::value;

  // Columns e_F1, e_F2, e_F3 in the root's components: (^R P^F)^T.
  template <class F>
  const matrix3& axes() const {
    return c_[index<F>()];
  }
  template <class F>
  const vector3& omega() const {
    static_assert(
        Level >= level::velocity,
        "kane: this evaluator computes no angular velocities; declare it with level::velocity or higher");
    return w_[index<F>()];
  }
  template <class F>
  const vector3& alpha() const {
    static_assert(
        Level >= level::acceleration,
        "kane: this evaluator computes no angular accelerations; declare it with level::acceleration");
    return a_[index<F>()];
  }

  // sin q_I and cos q_I: from the cache when a frame turns by q_I.
  template <std::size_t I>
  scalar sin_q() const {
    using std::sin;
    if constexpr (is_cached<I>())
      return trig_.sin(I);
    else
      return sin(st_->q[I - 1]);
  }
  template <std::size_t I>
  scalar cos_q() const {
    using std::cos;
    if constexpr (is_cached<I>())
      return trig_.cos(I);
    else
      return cos(st_->q[I - 1]);
  }

 private:
  static constexpr auto cached = detail::step_coordinates<closure>::value;
  template <std::size_t I>
  static constexpr bool is_cached() {
    for (std::size_t k : cached)
      if (k == I) return true;
    return false;
  }

  template <class F>
  static constexpr std::size_t index() {
    static_assert(detail::contains<F, closure>::value,
                  "kane: this evaluator does not hold the frame; list it (or a frame below it) in "
                  "evaluator<State, frames<...>>");
    if constexpr (detail::contains<F, closure>::value)
      return detail::index_of<F, closure>::value;
    else
      return 0;
  }

  template <class... F>
  void pass(detail::list<F...>) {
    (edge<F>(), ...);
  }

  template <class F>
  void edge() {
    if constexpr (!std::is_void_v<typename F::tree_parent>) {
      using P = typename F::tree_parent;
      using K = typename F::step::axis;
      constexpr std::size_t q = F::step::coordinate::index;
      constexpr std::size_t i = index<F>(), ip = index<P>();
      constexpr int p = detail::unit_axis<K>::principal;
      const scalar c = trig_.cos(q), s = trig_.sin(q);
      const matrix3& cp = c_[ip];
      matrix3& cf = c_[i];
      vector3 k;
      if constexpr (std::is_void_v<typename P::tree_parent>) {
        // The parent is a root: its axes are the identity.
        cf = detail::elementary<scalar, K>(c, s).transpose();
        if constexpr (p >= 0)
          k = vector3::Unit(p);
        else {
          constexpr auto kk = detail::unit_axis<K>::value;
          k = vector3(scalar(kk[0]), scalar(kk[1]), scalar(kk[2]));
        }
      } else if constexpr (p >= 0) {
        constexpr int a = (p + 1) % 3, b = (p + 2) % 3;  // e_Fa = c e_Pa + s e_Pb, e_Fb = -s e_Pa + c e_Pb
        cf.col(p) = cp.col(p);
        cf.col(a) = c * cp.col(a) + s * cp.col(b);
        cf.col(b) = c * cp.col(b) - s * cp.col(a);
        k = cp.col(p);
      } else {
        constexpr auto kk = detail::unit_axis<K>::value;
        cf.noalias() = cp * detail::elementary<scalar, K>(c, s).transpose();
        k = cp * vector3(scalar(kk[0]), scalar(kk[1]), scalar(kk[2]));
      }
      if constexpr (Level >= level::velocity) {
        const scalar qd = st_->qd[q - 1];
        w_[i] = w_[ip] + qd * k;
        if constexpr (Level >= level::acceleration)
          a_[i] = a_[ip] + st_->qdd[q - 1] * k + qd * w_[ip].cross(k);
      }
    }
  }

  const St* st_ = nullptr;
  detail::trig<scalar, St::nq> trig_{};
  std::array<matrix3, size> c_;
  std::array<vector3, size> w_;
  std::array<vector3, size> a_;
};

namespace detail {

template <class X>
struct is_evaluator : std::false_type {};
template <class St, class Fr, level L>
struct is_evaluator<evaluator<St, Fr, L>> : std::true_type {};

template <class Ev, class X>
typename Ev::scalar eval_scalar(const X& x, const Ev& ev);
template <class Ev, class V>
typename Ev::vector3 eval_vector(const V& v, const Ev& ev);

template <class Ev, class X>
typename Ev::scalar eval_scalar(const X& x, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (coordinate_info<X>::value || speed_info<X>::value)
    return ev.state()[x];
  else if constexpr (Parameter<X>)
    return ev.state()[parameter<X::index>{}];
  else if constexpr (std::is_same_v<X, time_variable>)
    return ev.state().t;
  else if constexpr (is_constant<X>::value)
    return S(X::num) / S(X::den);
  else if constexpr (std::is_same_v<X, literal>)
    return S(x.value);
  else if constexpr (is_v<X, add>)
    return eval_scalar(x.l, ev) + eval_scalar(x.r, ev);
  else if constexpr (is_v<X, sub>)
    return eval_scalar(x.l, ev) - eval_scalar(x.r, ev);
  else if constexpr (is_v<X, mul>)
    return eval_scalar(x.l, ev) * eval_scalar(x.r, ev);
  else if constexpr (is_v<X, quot>)
    return eval_scalar(x.l, ev) / eval_scalar(x.r, ev);
  else if constexpr (is_v<X, neg>)
    return -eval_scalar(x.x, ev);
  else if constexpr (std::is_same_v<X, unary<sin_fn, decltype(x.x)>> ||
                     std::is_same_v<X, unary<cos_fn, decltype(x.x)>>) {
    using Arg = decltype(x.x);
    constexpr bool is_sin = std::is_same_v<X, unary<sin_fn, Arg>>;
    if constexpr (coordinate_info<Arg>::value && Arg::order == 0) {
      if constexpr (is_sin)
        return ev.template sin_q<Arg::index>();
      else
        return ev.template cos_q<Arg::index>();
    } else {
      using std::cos, std::sin;
      const S a = eval_scalar(x.x, ev);
      if constexpr (is_sin)
        return sin(a);
      else
        return cos(a);
    }
  } else if constexpr (std::is_same_v<X, unary<sqrt_fn, decltype(x.x)>>) {
    using std::sqrt;
    return sqrt(eval_scalar(x.x, ev));
  } else if constexpr (power_info<X>::value) {
    const S a = eval_scalar(x.x, ev);
    constexpr int n = power_info<X>::n;
    S r = a;
    for (int k = 1; k < (n < 0 ? -n : n); ++k) r *= a;
    return n < 0 ? S(1) / r : r;
  } else if constexpr (is_v<X, call>)
    return x.f(eval_scalar(x.x, ev));
  else if constexpr (is_v<X, vdot>)
    return eval_vector(x.l, ev).dot(eval_vector(x.r, ev));
  else
    static_assert(!sizeof(X), "kane: evaluation of an unknown scalar node");
}

// Components in the root frame.
template <class Ev, class V>
typename Ev::vector3 eval_vector(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  using V3 = typename Ev::vector3;
  if constexpr (is_zero_vector_v<V>)
    return V3::Zero();
  else if constexpr (is_unit<V>::value) {
    using F = typename V::frame;
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return V3::Unit(V::index - 1);
    else
      return ev.template axes<F>().col(V::index - 1);
  } else if constexpr (is_v<V, scaled>) {
    const S s = eval_scalar(v.s, ev);
    return s * eval_vector(v.v, ev);
  } else if constexpr (is_v<V, vsum>)
    return eval_vector(v.l, ev) + eval_vector(v.r, ev);
  else if constexpr (is_v<V, vdiff>)
    return eval_vector(v.l, ev) - eval_vector(v.r, ev);
  else if constexpr (is_v<V, vneg>)
    return -eval_vector(v.v, ev);
  else if constexpr (is_v<V, vcross>) {
    const V3 l = eval_vector(v.l, ev);
    const V3 r = eval_vector(v.r, ev);
    return l.cross(r);
  } else if constexpr (is_v<V, omega>)
    return ev.template omega<typename V::frame>();
  else if constexpr (is_v<V, alpha>)
    return ev.template alpha<typename V::frame>();
  else if constexpr (is_v<V, angular_velocity_of> || is_v<V, angular_acceleration_of>)
    return eval_vector(expand(v), ev);
  else
    return eval_vector(v.v, ev);  // a kinematic quantity: its expression
}

}  // namespace detail

// The value of a scalar expression.
template <ScalarExpr X, class Ev>
requires detail::is_evaluator<Ev>::value typename Ev::scalar evaluate(const X& x, const Ev& ev) {
  return detail::eval_scalar(x, ev);
}

// ^A v: the components of the vector expression v in A.
template <Frame A, VectorExpr V, class Ev>
requires detail::is_evaluator<Ev>::value vec<A, typename Ev::scalar> express(const V& v, const Ev& ev) {
  using R = detail::root_of<A>;
  using VR = detail::root_frame_of_t<V>;
  static_assert(std::is_same_v<VR, root_frame> || std::is_same_v<VR, R>,
                "kane: no path of the frame tree joins the vector's frames and the frame of expression; "
                "express it in a frame of its own tree");
  const typename Ev::vector3 r = detail::eval_vector(v, ev);
  if constexpr (std::is_same_v<A, R>)
    return vec<A, typename Ev::scalar>(r);
  else
    return vec<A, typename Ev::scalar>(ev.template axes<A>().transpose() * r);
}

}  // namespace kane
