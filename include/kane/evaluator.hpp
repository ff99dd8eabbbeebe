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
// With a speed set (speeds.hpp), q' and q'' are first solved from u and u'.
// update(s) keeps a pointer to s: s must outlive the evaluations that follow.
// Evaluating allocates nothing and calls no sin or cos of a frame coordinate.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/angular_velocity.hpp"
#include "kane/derivative.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/solve.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/detail/v3.hpp"
#include "kane/expr.hpp"
#include "kane/speeds.hpp"
#include "kane/state.hpp"
#include "kane/status.hpp"
#include "kane/vec.hpp"
#include "kane/vector.hpp"

namespace kane {

template <class... F>
struct frames {};

// What the outward pass computes: orientations, + angular velocities, + angular accelerations.
enum class level { pose, velocity, acceleration };

namespace detail {
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

namespace detail {
template <class Ev, class X>
typename Ev::scalar eval_scalar(const X& x, const Ev& ev);

template <class Ev, class V>
v3<typename Ev::scalar> eval_vector(const V& v, const Ev& ev);
}  // namespace detail

// Speeds: void to read q' and q'' from the state; a speed set to solve them
// from the state's u and u'.
template <State St, class Frames, level Level = level::acceleration, class Speeds = void>
class evaluator;

template <State St, Frame... Fs, level Level, class Speeds>
class evaluator<St, frames<Fs...>, Level, Speeds> {
  static constexpr bool solves = !std::is_void_v<Speeds>;
  static constexpr bool direct = [] {  // q' = u or q' read from the state
    if constexpr (solves)
      return Speeds::identity;
    else
      return true;
  }();
  static constexpr std::size_t nq = St::nq;

 public:
  using state_type = St;
  using scalar = typename St::scalar;
  using speed_set = Speeds;
  using closure = typename detail::closure<Fs...>::type;
  static constexpr std::size_t size = detail::size<closure>::value;
  using matrix3 = Eigen::Matrix<scalar, 3, 3>;
  using vector3 = Eigen::Matrix<scalar, 3, 1>;
  using matrixn = Eigen::Matrix<scalar, int(nq), int(nq)>;
  using vectorn = Eigen::Matrix<scalar, int(nq), 1>;

  evaluator() {
    static_assert(!solves || SpeedSet<Speeds>,
                  "kane: the fourth argument of evaluator is a speed set (speeds.hpp)");
    if constexpr (solves) {
      static_assert(Speeds::n == nq, "kane: a speed set defines as many speeds as the state has coordinates");
      static_assert(St::nu >= nq, "kane: the state holds fewer speeds than the speed set defines");
      if constexpr (!Speeds::identity)
        static_assert(system::form.regular,
                      "kane: these speeds do not determine q' (Y = du/dq' is singular at every state: some "
                      "q' appears in no speed, or fewer speeds than q' involve them)");
    }
    init_roots(closure{});  // the pass writes every other frame
  }

  // The outward pass at s; s must outlive the evaluations that follow. With a
  // speed set, W and X at every level, q' and q'' from s.u and s.ud at the
  // velocity and acceleration levels; if Y is singular or not finite,
  // status() says so, and W (but for its structural zeros and ones), X, q',
  // q'' and all computed from them are NaN.
  KANE_FLATTEN void update(const St& s) {
    st_ = &s;
    const auto t = detail::make_trig<cached>(s);  // kept local: the pass reads it from registers
    constexpr bool velocity = Level >= level::velocity, acceleration = Level >= level::acceleration;
    if constexpr (!solves) {
      pass<true, velocity, acceleration>(closure{}, t);  // frame after frame, all levels at once
      store_trig(t);
    } else {  // Y, Z need the axes; Y', Z' the angular velocities
      pass<true, false, false>(closure{}, t);
      store_trig(t);
      if constexpr (!direct) solve_kinematic_equations();
      if constexpr (velocity) {
        solve_rates();
        pass<false, true, false>(closure{}, t);
      }
      if constexpr (acceleration) {
        solve_accelerations();
        pass<false, false, true>(closure{}, t);
      }
    }
  }

  const St& state() const { return *st_; }
  solve_status status() const { return status_; }

  // q_I, q_I', q_I'': from the state, or solved from the speeds.
  template <std::size_t I, std::size_t D>
  scalar coordinate_value() const {
    static_assert(I >= 1 && I <= nq,
                  "kane: this coordinate is beyond the state; declare the state with NQ >= I");
    static_assert(D <= 2, "kane: a state holds q, q' and q'' only");
    if constexpr (D == 0)
      return st_->q[I - 1];
    else if constexpr (D == 1)
      return solves ? qd_[I - 1] : st_->qd[I - 1];
    else
      return solves ? qdd_[I - 1] : st_->qdd[I - 1];
  }
  // q' = W u + X (W the identity and X zero without a speed set).
  matrixn W() const {
    matrixn w;
    for (std::size_t i = 0; i < nq; ++i)
      for (std::size_t j = 0; j < nq; ++j) w(i, j) = weight(i, j);
    return w;
  }
  vectorn X() const {
    vectorn x;
    for (std::size_t i = 0; i < nq; ++i) x(i) = offset(i);
    return x;
  }

  // W_sr and X_s (0-based): numbers where the structure of Y does not fix them.
  scalar weight(std::size_t s, std::size_t r) const {
    const auto kind = w_pattern()[s][r];
    return kind == detail::entry::other ? kde_w_[s][r] : scalar(kind == detail::entry::one);
  }
  scalar offset(std::size_t s) const { return offset_pattern()[s] ? kde_x_[s] : scalar(0); }
  // the stored numbers behind kde_weight<S + 1, R + 1> and kde_offset<S + 1>
  template <std::size_t S, std::size_t R>
  scalar stored_weight() const {
    static_assert(w_pattern()[S][R] == detail::entry::other);
    return kde_w_[S][R];
  }
  template <std::size_t S>
  scalar stored_offset() const {
    static_assert(offset_pattern()[S]);
    return kde_x_[S];
  }

  // Columns e_F1, e_F2, e_F3 in the root's components: (^R P^F)^T.
  template <class F>
  Eigen::Map<const matrix3> axes() const {
    return Eigen::Map<const matrix3>(c_[index<F>()].data());
  }
  template <class F>
  Eigen::Map<const vector3> omega() const {
    static_assert(
        Level >= level::velocity,
        "kane: this evaluator computes no angular velocities; declare it with level::velocity or higher");
    return Eigen::Map<const vector3>(w_[index<F>()].data());
  }
  template <class F>
  Eigen::Map<const vector3> alpha() const {
    static_assert(
        Level >= level::acceleration,
        "kane: this evaluator computes no angular accelerations; declare it with level::acceleration");
    return Eigen::Map<const vector3>(a_[index<F>()].data());
  }

  // sin q_I and cos q_I: from the cache when a frame turns by q_I.
  template <std::size_t I>
  scalar sin_q() const {
    using std::sin;
    if constexpr (is_cached<I>())
      return trig_.template sin<I>();
    else
      return sin(st_->q[I - 1]);
  }
  template <std::size_t I>
  scalar cos_q() const {
    using std::cos;
    if constexpr (is_cached<I>())
      return trig_.template cos<I>();
    else
      return cos(st_->q[I - 1]);
  }

 private:
  static constexpr auto cached = detail::step_coordinates<closure>::value;
  using trig_type = detail::trig<scalar, cached>;
  template <std::size_t I>
  static constexpr bool is_cached() {
    return trig_type::template holds<I>();
  }
  // element by element: a wide copy of values just written narrowly would stall
  void store_trig(const trig_type& t) {
    for (std::size_t k = 0; k < trig_type::size; ++k) trig_.s[k] = t.s[k], trig_.c[k] = t.c[k];
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

  template <class F>
  static constexpr bool is_edge = !std::is_void_v<typename F::tree_parent>;

  template <class... F>
  void init_roots(detail::list<F...>) {
    (
        [&] {
          if constexpr (!is_edge<F>)
            c_[index<F>()] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, w_[index<F>()] = {}, a_[index<F>()] = {};
        }(),
        ...);
  }

  template <bool Pose, bool Velocity, bool Acceleration, class... F>
  void pass(detail::list<F...>, const trig_type& t) {
    (
        [&] {
          if constexpr (Pose) pose_edge<F>(t);
          if constexpr (Velocity) velocity_edge<F>();
          if constexpr (Acceleration) acceleration_edge<F>();
        }(),
        ...);
  }

  using v3 = detail::v3<scalar>;
  template <class F>
  v3 column(int j) const {
    return detail::load3(c_[index<F>()].data() + 3 * j);
  }

  // The axis k of the edge above F, in the root's components (fixed in both frames).
  template <class F>
  v3 edge_axis() const {
    using K = typename F::step::axis;
    constexpr int p = detail::unit_axis<K>::principal;
    if constexpr (p >= 0) {
      return column<F>(p);
    } else {
      constexpr auto k = detail::unit_axis<K>::value;
      return scalar(k[0]) * column<F>(0) + scalar(k[1]) * column<F>(1) + scalar(k[2]) * column<F>(2);
    }
  }

  template <class F>
  void pose_edge(const trig_type& t) {
    if constexpr (is_edge<F>) {
      using P = typename F::tree_parent;
      using K = typename F::step::axis;
      constexpr std::size_t q = F::step::coordinate::index;
      constexpr int p = detail::unit_axis<K>::principal;
      const scalar c = t.template cos<q>(), s = t.template sin<q>();
      scalar* cf = c_[index<F>()].data();
      if constexpr (p >= 0) {
        constexpr int a = (p + 1) % 3, b = (p + 2) % 3;  // e_Fa = c e_Pa + s e_Pb, e_Fb = c e_Pb - s e_Pa
        if constexpr (!is_edge<P>) {                     // the parent's axes are the identity
          c_[index<F>()] = {};
          cf[3 * p + p] = scalar(1);
          cf[3 * a + a] = c, cf[3 * a + b] = s;
          cf[3 * b + a] = -s, cf[3 * b + b] = c;
        } else {
          const v3 ea = column<P>(a), eb = column<P>(b);
          detail::store3(cf + 3 * p, column<P>(p));
          detail::store3(cf + 3 * a, c * ea + s * eb);
          detail::store3(cf + 3 * b, c * eb - s * ea);
        }
      } else {  // e_Fj = sum_k (^P P^F)_jk e_Pk
        const matrix3 e = detail::elementary<scalar, K>(c, s);
        Eigen::Map<matrix3> m(cf);
        if constexpr (!is_edge<P>)
          m = e.transpose();
        else
          m.noalias() = axes<P>() * e.transpose();
      }
    }
  }

  template <class F>
  void velocity_edge() {
    if constexpr (is_edge<F>) {
      constexpr std::size_t q = F::step::coordinate::index;
      const v3 wp = detail::load3(w_[index<typename F::tree_parent>()].data());
      detail::store3(w_[index<F>()].data(), wp + coordinate_value<q, 1>() * edge_axis<F>());
    }
  }

  template <class F>
  void acceleration_edge() {
    if constexpr (is_edge<F>) {
      constexpr std::size_t q = F::step::coordinate::index;
      constexpr std::size_t ip = index<typename F::tree_parent>();
      const v3 k = edge_axis<F>();
      const v3 wp = detail::load3(w_[ip].data()), ap = detail::load3(a_[ip].data());
      detail::store3(a_[index<F>()].data(),
                     ap + coordinate_value<q, 2>() * k + coordinate_value<q, 1>() * detail::cross3(wp, k));
    }
  }

  template <std::size_t R>
  static constexpr auto definition() {
    return std::get<R>(Speeds::definitions);
  }
  using system = detail::kde_system<std::conditional_t<solves, Speeds, qdot_speeds<1>>>;
  static constexpr detail::pattern<nq, nq> w_pattern() {
    if constexpr (direct)
      return detail::identity_pattern<nq>();
    else
      return system::x;
  }
  static constexpr std::array<bool, nq> offset_pattern() {
    if constexpr (direct)
      return {};
    else
      return system::offset;
  }

  // Y q' + Z = u, so q' = W u + X with W = Y^-1 (detail/solve.hpp) and X = -W Z:
  // W and X depend on q alone. The zeros and ones of W are written once, by the constructor.
  void solve_kinematic_equations() {
    detail::table<scalar, nq, nq> y;
    detail::static_for<nq * nq>([&](auto rc) {
      constexpr std::size_t r = rc / nq, c = rc % nq;
      if constexpr (system::m[r][c] == detail::entry::other)
        y[r][c] = detail::eval_scalar(diff(definition<r>(), coordinate<c + 1, 1>{}), *this);
    });
    status_ = detail::solve_structured<system, false>(y, y, kde_w_);
    std::array<scalar, nq> z;
    detail::static_for<nq>([&](auto r) {
      if constexpr (system::z[r] != detail::entry::zero)
        z[r] = -detail::eval_scalar(detail::at_rest(definition<r>()), *this);
    });
    detail::static_for<nq>([&](auto c) {
      if constexpr (system::offset[c]) kde_x_[c] = apply_row<c, false>(z);
    });
    if (status_ != solve_status::ok)
      detail::static_for<nq>([&](auto c) {
        if constexpr (system::offset[c]) kde_x_[c] = std::numeric_limits<scalar>::quiet_NaN();
      });
  }
  void solve_rates() {
    if constexpr (direct) {  // u = q'
      for (std::size_t i = 0; i < nq; ++i) qd_[i] = st_->u[i];
    } else {
      qd_ = apply<true>(st_->u);
      if (status_ != solve_status::ok) qd_.fill(std::numeric_limits<scalar>::quiet_NaN());
    }
  }
  // (W v)_c (+ X_c), skipping the zeros of W and X.
  template <std::size_t C, bool Offset, class V>
  scalar apply_row(const V& v) const {
    scalar sum = scalar(0);
    if constexpr (Offset && system::offset[C]) sum = kde_x_[C];
    detail::static_for<nq>([&](auto j) {
      if constexpr (system::x[C][j] == detail::entry::one)
        sum += v[j];
      else if constexpr (system::x[C][j] == detail::entry::other)
        sum += kde_w_[C][j] * v[j];
    });
    return sum;
  }
  template <bool Offset, class V>
  std::array<scalar, nq> apply(const V& v) const {
    std::array<scalar, nq> out;
    detail::static_for<nq>([&](auto c) { out[c] = apply_row<c, Offset>(v); });
    return out;
  }

  // u' = Y q'' + Y' q' + Z', so q'' = W (u' - Y' q' - Z').
  void solve_accelerations() {
    if constexpr (Speeds::identity) {
      for (std::size_t i = 0; i < nq; ++i) qdd_[i] = st_->ud[i];
    } else {
      std::array<scalar, nq> v;
      detail::static_for<nq>([&](auto r) {
        scalar sum = st_->ud[r];
        if constexpr (!is_zero_v<decltype(dt(detail::at_rest(definition<r>())))>)
          sum -= detail::eval_scalar(dt(detail::at_rest(definition<r>())), *this);
        detail::static_for<nq>([&](auto c) {
          constexpr auto yd = dt(diff(definition<r>(), coordinate<c + 1, 1>{}));
          if constexpr (!is_zero_v<std::remove_cv_t<decltype(yd)>>)
            sum -= detail::eval_scalar(yd, *this) * qd_[c];
        });
        v[r] = sum;
      });
      qdd_ = apply<false>(v);
    }
  }

  const St* st_ = nullptr;
  solve_status status_ = solve_status::ok;
  std::array<scalar, nq> qd_{};
  std::array<scalar, nq> qdd_{};
  detail::table<scalar, nq, nq> kde_w_;  // W, row after row
  std::array<scalar, nq> kde_x_;
  trig_type trig_;
  std::array<std::array<scalar, 9>, size> c_;  // e_F1, e_F2, e_F3 in R, column after column
  std::array<std::array<scalar, 3>, size> w_;
  std::array<std::array<scalar, 3>, size> a_;
};

namespace detail {

template <class X>
struct is_evaluator : std::false_type {};
template <class St, class Fr, level L, class Sp>
struct is_evaluator<evaluator<St, Fr, L, Sp>> : std::true_type {};

// e_Ri of a root frame R: components known at compile time.
template <class V>
struct root_unit : std::false_type {};
template <class F, int I>
struct root_unit<unit<F, I>> : std::bool_constant<std::is_void_v<typename F::tree_parent>> {};
template <int I, class S>
S component(const v3<S>& a) {
  return I == 1 ? a.x : I == 2 ? a.y : a.z;
}
// a x e_Ri
template <int I, class S>
v3<S> cross_unit(const v3<S>& a) {
  if constexpr (I == 1)
    return {S(0), a.z, -a.y};
  else if constexpr (I == 2)
    return {-a.z, S(0), a.x};
  else
    return {a.y, -a.x, S(0)};
}

template <class Ev, class X>
typename Ev::scalar eval_scalar(const X& x, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (coordinate_info<X>::value)
    return ev.template coordinate_value<X::index, X::order>();
  else if constexpr (speed_info<X>::value)
    return ev.state()[x];
  else if constexpr (Parameter<X>)
    return ev.state()[parameter<X::index>{}];
  else if constexpr (std::is_same_v<X, time_variable>)
    return ev.state().t;
  else if constexpr (is_constant<X>::value)
    return S(X::num) / S(X::den);
  else if constexpr (kde_info<X>::value) {
    if constexpr (requires { X::column; })
      return ev.template stored_weight<X::row - 1, X::column - 1>();
    else
      return ev.template stored_offset<X::row - 1>();
  } else if constexpr (std::is_same_v<X, literal>)
    return S(x.value);
  else if constexpr (is_fixed<X>::value)
    return S(X::value);
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
  else if constexpr (is_v<X, unary>) {
    using Fn = typename unary_info<X>::fn;
    using Arg = decltype(x.x);
    if constexpr (!std::is_same_v<Fn, sqrt_fn> && Coordinate<Arg>) {
      if constexpr (std::is_same_v<Fn, sin_fn>)
        return ev.template sin_q<Arg::index>();
      else
        return ev.template cos_q<Arg::index>();
    } else {
      using std::cos, std::sin, std::sqrt;
      const S a = eval_scalar(x.x, ev);
      if constexpr (std::is_same_v<Fn, sin_fn>)
        return sin(a);
      else if constexpr (std::is_same_v<Fn, cos_fn>)
        return cos(a);
      else
        return sqrt(a);
    }
  } else if constexpr (power_info<X>::value) {
    const S a = eval_scalar(x.x, ev);
    constexpr int n = power_info<X>::n;
    S r = a;
    for (int k = 1; k < (n < 0 ? -n : n); ++k) r *= a;
    return n < 0 ? S(1) / r : r;
  } else if constexpr (is_v<X, call>)
    return x.f(eval_scalar(x.x, ev));
  else if constexpr (is_v<X, vdot>) {
    if constexpr (root_unit<decltype(x.r)>::value)  // v . e_Ri: a component
      return component<decltype(x.r)::index>(eval_vector(x.l, ev));
    else if constexpr (root_unit<decltype(x.l)>::value)
      return component<decltype(x.l)::index>(eval_vector(x.r, ev));
    else
      return dot3(eval_vector(x.l, ev), eval_vector(x.r, ev));
  } else
    static_assert(!sizeof(X), "kane: evaluation of an unknown scalar node");
}

// Components in the root frame.
template <class Ev, class V>
v3<typename Ev::scalar> eval_vector(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (is_zero_vector_v<V>)
    return {S(0), S(0), S(0)};
  else if constexpr (is_unit<V>::value) {
    using F = typename V::frame;
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return {S(V::index == 1), S(V::index == 2), S(V::index == 3)};
    else
      return load3(ev.template axes<F>().data() + 3 * (V::index - 1));
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
    if constexpr (root_unit<decltype(v.r)>::value)
      return cross_unit<decltype(v.r)::index>(eval_vector(v.l, ev));
    else if constexpr (root_unit<decltype(v.l)>::value)
      return -cross_unit<decltype(v.l)::index>(eval_vector(v.r, ev));
    else
      return cross3(eval_vector(v.l, ev), eval_vector(v.r, ev));
  } else if constexpr (is_v<V, omega>)
    return load3(ev.template omega<typename V::frame>().data());
  else if constexpr (is_v<V, alpha>)
    return load3(ev.template alpha<typename V::frame>().data());
  else if constexpr (is_v<V, angular_velocity_of> || is_v<V, angular_acceleration_of>)
    return eval_vector(expand(v), ev);
  else
    return eval_vector(v.v, ev);  // a kinematic quantity: its expression
}

// ^A components of the root components r.
template <class A, class Ev>
v3<typename Ev::scalar> in_frame(const v3<typename Ev::scalar>& r, const Ev& ev) {
  if constexpr (std::is_same_v<A, root_of<A>>)
    return r;
  else {
    const auto* c = ev.template axes<A>().data();
    return {dot3(load3(c), r), dot3(load3(c + 3), r), dot3(load3(c + 6), r)};
  }
}

}  // namespace detail

// The value of a scalar expression.
template <ScalarExpr X, class Ev>
requires detail::is_evaluator<Ev>::value KANE_FLATTEN typename Ev::scalar evaluate(const X& x, const Ev& ev) {
  return detail::eval_scalar(x, ev);
}

// ^A v: the components of the vector expression v in A.
template <Frame A, VectorExpr V, class Ev>
requires detail::is_evaluator<Ev>::value KANE_FLATTEN vec<A, typename Ev::scalar> express(const V& v,
                                                                                          const Ev& ev) {
  using R = detail::root_of<A>;
  using VR = detail::root_frame_of_t<V>;
  static_assert(std::is_same_v<VR, root_frame> || std::is_same_v<VR, R>,
                "kane: no path of the frame tree joins the vector's frames and the frame of expression; "
                "express it in a frame of its own tree");
  const auto r = detail::in_frame<A>(detail::eval_vector(v, ev), ev);
  return vec<A, typename Ev::scalar>(r.x, r.y, r.z);
}

}  // namespace kane
