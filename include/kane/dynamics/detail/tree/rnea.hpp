// Inverse dynamics by inward sums (the recursive Newton-Euler algorithm):
// Kane's -(F_r + F*_r) = sum over items of v_r . (m a - R) + w_r . (I alpha +
// w x I w - T), regrouped. In a system of joint form (joint_form.hpp) every item
// below the edge of u_r turns about k_r through o_r, so
//   M u' - f = tau,   tau_r = k_r . n_r,
// with n_r the moment about o_r of the items below the edge. In body coordinates
// (body_frames.hpp), outward: w_F = E^T w_P + u k, alpha_F = E^T alpha_P + u' k +
// u (E^T w_P) x k, a_F = E^T (a_P + alpha_P x t + w_P x (w_P x t)), a_O = -g
// (gravity as an acceleration of the base); per item f = m a_C - R,
// n = I alpha + w x I w - T + c x f about o_F; inward: f_P += E f, n_P += E n + t x E f.
// A free joint (joint_form.hpp) starts the pass with w = u_1..3, alpha = u_1..3' and
// a = E^T (a_O + u_4..6') and ends it with tau_1..3 = n, tau_4..6 = E f.
// At u' = 0 (Rest) tau = -f. Cost: O(n).
#pragma once

#include <array>
#include <cstddef>
#include <tuple>

#include <Eigen/Core>

#include "kane/detail/choices.hpp"
#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/crba.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// u_r (Order 1) or u_r' (Order 2) of the evaluator's state, u_r = q_r'.
template <std::size_t Order, class Ev>
KANE_ALWAYS_INLINE typename Ev::scalar joint_rate(const Ev& ev, std::size_t r) {
  const auto& s = ev.state();
  if constexpr (std::is_void_v<typename Ev::speed_set>)
    return Order == 1 ? s.qd[r] : s.qdd[r];
  else
    return Order == 1 ? s.u[r] : s.ud[r];
}

// -g, the acceleration of the root that stands for gravity, and its pattern: the sum of the
// system's gravity vectors, in the root's components.
template <class X, class R>
constexpr std::array<entry, 3> gravity_pattern() {
  if constexpr (!is_gravity<X>)
    return {entry::zero, entry::zero, entry::zero};
  else {
    using V = std::remove_cv_t<decltype(X::vector)>;
    using F = typename fixed_frame_of<V>::type;
    if constexpr (std::is_same_v<F, R> || std::is_same_v<F, no_frame>)
      return scaled_pattern(own_pattern<V>());
    else
      return {entry::other, entry::other, entry::other};
  }
}
template <class R, class... X>
constexpr std::array<entry, 3> base_pattern(list<X...>) {
  std::array<entry, 3> out{entry::zero, entry::zero, entry::zero};
  for (const auto& p :
       {std::array<entry, 3>{entry::zero, entry::zero, entry::zero}, gravity_pattern<X, R>()...})
    for (std::size_t i = 0; i < 3; ++i)
      if (p[i] != entry::zero) out[i] = entry::other;
  return out;
}
template <class Sys, class R, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> base_acceleration(const Ev& ev) {
  using S = typename Ev::scalar;
  return v3<S>{S(0), S(0), S(0)} - eval_vector<memo_use::fresh>(gravity_of(typename Sys::items{}), ev);
}

// The applied load X at c (pattern C, components in F) subtracted from (f, n): f -= R and
// n -= c x R for a force R, n -= T for a torque T; R or T is X's vector, or Vector.
template <class X, class F, auto C, auto Vector = X::vector, class Ev, class V>
KANE_ALWAYS_INLINE void subtract_load(V& f, V& n, const V& c, const Ev& ev) {
  if constexpr (is_zero_vector_v<std::remove_cvref_t<decltype(Vector)>>)
    return;
  else if constexpr (is_force<X>) {
    const V r = in_frame<F>(eval_vector<memo_use::fresh>(Vector, ev), ev);
    f = f - r;
    if constexpr (!all_zero(C)) n = n - cross_from<C>(c, r);
  } else if constexpr (is_torque<X>)
    n = n - in_frame<F>(eval_vector<memo_use::fresh>(Vector, ev), ev);
}

// tau from the forces f and moments n of each frame's own items (about its origin, in its
// components), summed inward: f_P += E f, n_P += E n + t x E f; tau_r = k_r . n, a free joint's
// tau_1..3 = n and tau_4..6 = E f. -tau with Negated.
template <class JF, bool Negated, class S, class Ev, class Out>
KANE_ALWAYS_INLINE void inward_forces(const body_frames<JF, Ev>& bf, std::array<v3<S>, JF::nf>& f,
                                      std::array<v3<S>, JF::nf>& n, Out& tau) {
  using BF = body_frames<JF, Ev>;
  static constexpr auto& t = JF::table;
  static_for<JF::nf - 1>([&](auto j) KANE_ALWAYS_INLINE_LAMBDA {  // leaves first
    constexpr std::size_t g = JF::nf - 1 - j, p = std::size_t(t.parent[g]);
    constexpr int r = t.speed[g];
    if constexpr (r >= 0) {
      using F = frame_at<JF, g>;
      const S x = dot_along<joint_axis_pattern<F>()>(n[g], joint_axis_in_frame<F, S>());
      tau(Eigen::Index(r)) = Negated ? -x : x;
    } else if constexpr (int(g) == t.free) {  // n about the origin in F's components, f in the root's
      const v3<S> fo = std::get<g>(bf.e).up(f[g]);
      const std::array<S, 6> x{n[g].x, n[g].y, n[g].z, fo.x, fo.y, fo.z};
      for (std::size_t k = 0; k < 6; ++k) tau(Eigen::Index(k)) = Negated ? -x[k] : x[k];
    }
    if constexpr (p > 0) {
      constexpr auto O = BF::offset_pattern(g);
      const auto& e = std::get<g>(bf.e);
      const v3<S> fp = e.up(f[g]);
      f[p] = f[p] + fp, n[p] = n[p] + e.up(n[g]);
      if constexpr (!all_zero(O)) n[p] = n[p] + cross_from<O>(bf.offset[g], fp);
    }
  });
}

// tau = M u' - f of the joint-form system Sys (u' of the state, or 0 with Rest); -tau with Negated.
template <rates Rates, class JF, class Sys, sign Sign = sign::plus, class Ev, class Out>
KANE_ALWAYS_INLINE void joint_forces(const body_frames<JF, Ev>& bf, const Ev& ev, Out& tau) {
  constexpr bool Rest = Rates == rates::at_rest, Negated = Sign == sign::minus;
  using S = typename Ev::scalar;
  using vec = v3<S>;
  static constexpr auto& t = JF::table;
  constexpr std::size_t nf = JF::nf;
  const vec zero{S(0), S(0), S(0)};
  std::array<vec, nf> w, alpha, a, n, f;
  w[0] = zero, alpha[0] = zero;
  constexpr auto G = base_pattern<frame_at<JF, 0>>(typename Sys::items{});
  a[0] = base_acceleration<Sys, frame_at<JF, 0>>(ev);
  using BF = body_frames<JF, Ev>;
  using known = known_inertias<JF, Sys, BF>;
  static_for<nf - 1>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t g = i + 1, p = std::size_t(t.parent[g]);
    constexpr int r = t.speed[g];
    constexpr auto O = BF::offset_pattern(g);
    const auto& e = std::get<g>(bf.e);
    const vec& o = bf.offset[g];
    if constexpr (int(g) == t.free) {  // w = u_1..3, alpha = u_1..3', a = E^T (a_O + u_4..6')
      vec ao = a[0];
      if constexpr (!Rest) ao = ao + vec{joint_rate<2>(ev, 3), joint_rate<2>(ev, 4), joint_rate<2>(ev, 5)};
      a[g] = e.down(ao);
      w[g] = {joint_rate<1>(ev, 0), joint_rate<1>(ev, 1), joint_rate<1>(ev, 2)};
      alpha[g] = Rest ? zero : vec{joint_rate<2>(ev, 0), joint_rate<2>(ev, 1), joint_rate<2>(ev, 2)};
    } else if constexpr (p == 0) {  // the root does not turn: a = E^T a_O, w = u k, alpha = u' k
      a[g] = e.template down_along<G>(a[0]);
      if constexpr (r < 0)
        w[g] = zero, alpha[g] = zero;
      else {
        using F = frame_at<JF, g>;
        constexpr auto K = joint_axis_pattern<F>();
        const vec k = joint_axis_in_frame<F, S>();
        w[g] = add_along<K, onto::zero>(zero, joint_rate<1>(ev, std::size_t(r)), k);
        alpha[g] = Rest ? zero : add_along<K, onto::zero>(zero, joint_rate<2>(ev, std::size_t(r)), k);
      }
    } else {
      const vec wp = e.down(w[p]);
      if constexpr (all_zero(O))
        a[g] = e.down(a[p]);
      else
        a[g] = e.down(a[p] + cross_along<O>(alpha[p], o) + cross3(w[p], cross_along<O>(w[p], o)));
      if constexpr (r < 0)
        w[g] = wp, alpha[g] = e.down(alpha[p]);
      else {
        using F = frame_at<JF, g>;
        constexpr auto K = joint_axis_pattern<F>();
        const vec k = joint_axis_in_frame<F, S>();
        const S u = joint_rate<1>(ev, std::size_t(r));
        w[g] = add_along<K, onto::sum>(wp, u, k);
        alpha[g] = e.down(alpha[p]) + u * cross_along<K>(wp, k);
        if constexpr (!Rest)
          alpha[g] = add_along<K, onto::sum>(alpha[g], joint_rate<2>(ev, std::size_t(r)), k);
      }
    }
    // the frame's own items of known (m, h, J) about its origin, constants: f = m a + alpha x h +
    // w x (w x h), n = J alpha + w x J w + h x a; the others below
    constexpr composite_inertia<double> m = known::own[g];
    if constexpr (known::value &&
                  (m.mass != 0 || m.h.x != 0 || m.h.y != 0 || m.h.z != 0 || m.i != std::array<double, 6>{})) {
      const vec h{S(m.h.x), S(m.h.y), S(m.h.z)};
      const sym3<S> jo{S(m.i[0]), S(m.i[1]), S(m.i[2]), S(m.i[3]), S(m.i[4]), S(m.i[5])};
      constexpr std::array<entry, 3> H = {entry_of_number(m.h.x) == entry::zero ? entry::zero : entry::other,
                                          entry_of_number(m.h.y) == entry::zero ? entry::zero : entry::other,
                                          entry_of_number(m.h.z) == entry::zero ? entry::zero : entry::other};
      const vec& wg = w[g];
      const vec& ag = alpha[g];
      f[g] = S(m.mass) * a[g] + cross_along<H>(ag, h) + cross3(wg, cross_along<H>(wg, h));
      n[g] = sym_times(jo, ag) + cross3(wg, sym_times(jo, wg)) + cross_from<H>(h, a[g]);
    } else
      n[g] = zero, f[g] = zero;
  });
  [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
    (
        [&]() KANE_ALWAYS_INLINE_LAMBDA {
          constexpr int g = t.item_frame[I];
          if constexpr (!is_gravity<X> && g > 0) {
            using F = frame_at<JF, std::size_t(g)>;
            constexpr int ip = t.item_point[I];
            constexpr auto C = BF::local_pattern(ip, g);
            const vec c = bf.template local<ip, g>();
            vec& fg = f[std::size_t(g)];
            vec& ng = n[std::size_t(g)];
            if constexpr ((is_particle<X> || is_body<X>)&&known::value) {
              // in the outward pass, above
            } else if constexpr (is_particle<X> || is_body<X>) {
              const vec& wg = w[std::size_t(g)];
              const vec& ag = alpha[std::size_t(g)];
              vec ac = a[std::size_t(g)];
              if constexpr (!all_zero(C)) ac = ac + cross_along<C>(ag, c) + cross3(wg, cross_along<C>(wg, c));
              const vec fc = S(eval_scalar(X::mass, ev)) * ac;
              fg = fg + fc;
              if constexpr (!all_zero(C)) ng = ng + cross_from<C>(c, fc);
              if constexpr (is_body<X>) {
                const sym3<S> ic = body_inertia<X>(ev);
                ng = ng + sym_times(ic, ag) + cross3(wg, sym_times(ic, wg));
              }
            } else
              subtract_load<X, F, C>(fg, ng, c, ev);
          }
        }(),
        ...);
  }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  inward_forces<JF, Negated>(bf, f, n, tau);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
