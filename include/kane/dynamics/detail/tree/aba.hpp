// Forward dynamics by articulated bodies (the articulated-body algorithm):
// u' of Kane's M u' = f without forming M. In a system of joint form
// (joint_form.hpp) each speed turns its edge about k through o (S = (k, 0) in
// body coordinates, body_frames.hpp); spatial vectors are (angular, linear)
// about o_F in F's components, inertias I = [A B; B^T C] (momentum about o_F,
// linear momentum). Outward: w_F = E^T w_P + u k, v_F = E^T (v_P + w_P x t),
// c_F = (w_F x k u, v_F x k u), I_F and the bias p_F = v x* I v - f_ext of F's
// items. Inward: U = I S, D = S.U, d = -S.p; I^a = I - U U^T / D,
// p^a = p + I^a c + U d / D carried to the parent (rotated by E, moved by t:
// A - B[t] + [t]B^T - [t]C[t], B + [t]C, C). Outward: a' = X a_P + c,
// u' = (d - U.a') / D, a = a' + S u', from a_O = (0, -g).
// Cost: O(n), about 400 operations a speed; for few speeds M and a fixed-size
// Cholesky factorization cost less (forward_dynamics.hpp chooses).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <tuple>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/crba.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S>
using mat3 = Eigen::Matrix<S, 3, 3>;
template <class S>
KANE_ALWAYS_INLINE mat3<S> skew(const v3<S>& t) {
  mat3<S> m;
  m << S(0), -t.z, t.y, t.z, S(0), -t.x, -t.y, t.x, S(0);
  return m;
}
template <class S>
KANE_ALWAYS_INLINE v3<S> times3(const mat3<S>& m, const v3<S>& v) {
  return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z, m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
          m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}
template <class S>
KANE_ALWAYS_INLINE v3<S> times3_transposed(const mat3<S>& m, const v3<S>& v) {
  return {m(0, 0) * v.x + m(1, 0) * v.y + m(2, 0) * v.z, m(0, 1) * v.x + m(1, 1) * v.y + m(2, 1) * v.z,
          m(0, 2) * v.x + m(1, 2) * v.y + m(2, 2) * v.z};
}
// E m E^T
template <class S, int A>
KANE_ALWAYS_INLINE mat3<S> turned_up(const turn<S, A>& e, const mat3<S>& m) {
  if constexpr (A < 0)
    return e.e * m * e.e.transpose();
  else {
    constexpr int b = (A + 1) % 3, d = (A + 2) % 3;
    mat3<S> o = m;
    for (int j = 0; j < 3; ++j) {
      const S x = o(b, j), y = o(d, j);
      o(b, j) = e.c * x - e.s * y, o(d, j) = e.s * x + e.c * y;
    }
    for (int i = 0; i < 3; ++i) {
      const S x = o(i, b), y = o(i, d);
      o(i, b) = e.c * x - e.s * y, o(i, d) = e.s * x + e.c * y;
    }
    return o;
  }
}

template <class S>
struct articulated {
  mat3<S> a, b, c;  // [A B; B^T C]
  v3<S> n, f;       // bias force
};

// u' of the joint-form system Sys; false where an articulated inertia along a speed is not positive.
template <class JF, class Sys, class Ev, class Out>
KANE_ALWAYS_INLINE bool articulated_accelerations(const body_frames<JF, Ev>& bf, const Ev& ev, Out& ud) {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  using BF = body_frames<JF, Ev>;
  static constexpr auto& t = JF::table;
  constexpr std::size_t nf = JF::nf, n = JF::n;
  const vec zero{S(0), S(0), S(0)};
  std::array<vec, nf> w, v, cw, cv;
  std::array<articulated<S>, nf> x;
  std::array<vec, n> uw, uv;
  std::array<S, n> dd, dn;
  w[0] = zero, v[0] = zero;
  static_for<nf - 1>([&](auto i) {  // velocities, bias accelerations, rigid inertias
    constexpr std::size_t g = i + 1, p = std::size_t(t.parent[g]);
    constexpr int r = t.speed[g];
    constexpr auto O = BF::offset_pattern(g);
    const auto& e = std::get<g>(bf.e);
    const vec wp = e.down(w[p]);
    v[g] = all_zero(O) ? e.down(v[p]) : e.down(v[p] + cross_along<O>(w[p], bf.offset[g]));
    if constexpr (r < 0)
      w[g] = wp, cw[g] = zero, cv[g] = zero;
    else {
      using F = frame_at<JF, g>;
      constexpr auto K = joint_axis_pattern<F>();
      const vec k = joint_axis_in_frame<F, S>();
      const S u = joint_rate<1>(ev, std::size_t(r));
      w[g] = add_along<K, onto::sum>(wp, u, k);
      cw[g] = u * cross_along<K>(w[g], k), cv[g] = u * cross_along<K>(v[g], k);
    }
    x[g].a.setZero(), x[g].b.setZero(), x[g].c.setZero(), x[g].n = zero, x[g].f = zero;
  });
  composite_inertia<S> zero_inertia{S(0), zero, {S(0), S(0), S(0), S(0), S(0), S(0)}};
  std::array<composite_inertia<S>, nf> rigid;
  rigid.fill(zero_inertia);
  [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
    (
        [&] {
          constexpr int g = t.item_frame[I];
          if constexpr (!is_gravity<X> && g > 0) {
            using F = frame_at<JF, std::size_t(g)>;
            constexpr int ip = t.item_point[I];
            constexpr auto C = BF::local_pattern(ip, g);
            const vec c = bf.template local<ip, g>();
            if constexpr (is_body<X> || is_particle<X>)
              add_item_mass<X, C>(rigid[std::size_t(g)], c, ev);
            else  // -f_ext
              subtract_load<X, F, C>(x[std::size_t(g)].f, x[std::size_t(g)].n, c, ev);
          }
        }(),
        ...);
  }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  static_for<nf - 1>([&](auto i) {  // I = [i [h]; -[h] m 1], p = v x* I v - f_ext
    constexpr std::size_t g = i + 1;
    const composite_inertia<S>& q = rigid[g];
    articulated<S>& y = x[g];
    y.a << q.i[0], q.i[3], q.i[5], q.i[3], q.i[1], q.i[4], q.i[5], q.i[4], q.i[2];
    y.b = skew(q.h);
    y.c = mat3<S>::Identity() * q.mass;
    const vec hh = sym_times(q.i, w[g]) + cross3(q.h, v[g]), ll = q.mass * v[g] - cross3(q.h, w[g]);
    y.n = y.n + cross3(w[g], hh) + cross3(v[g], ll), y.f = y.f + cross3(w[g], ll);
  });
  bool ok = true;
  static_for<nf - 1>([&](auto j) {  // leaves first
    constexpr std::size_t g = nf - 1 - j, p = std::size_t(t.parent[g]);
    constexpr int r = t.speed[g];
    articulated<S>& y = x[g];
    if constexpr (r >= 0) {
      using F = frame_at<JF, g>;
      const vec k = joint_axis_in_frame<F, S>();
      uw[r] = times3(y.a, k), uv[r] = times3_transposed(y.b, k);
      dd[r] = dot3(k, uw[r]), dn[r] = -dot3(k, y.n);
      ok = ok && dd[r] > S(0);
      if constexpr (p > 0) {
        const S inv = S(1) / dd[r];
        const Eigen::Matrix<S, 3, 1> a1(uw[r].x, uw[r].y, uw[r].z), b1(uv[r].x, uv[r].y, uv[r].z);
        y.a -= inv * a1 * a1.transpose(), y.b -= inv * a1 * b1.transpose(), y.c -= inv * b1 * b1.transpose();
        const S s = dn[r] * inv;
        y.n = y.n + times3(y.a, cw[g]) + times3(y.b, cv[g]) + s * uw[r];
        y.f = y.f + times3_transposed(y.b, cw[g]) + times3(y.c, cv[g]) + s * uv[r];
      }
    }
    if constexpr (p > 0) {
      const auto& e = std::get<g>(bf.e);
      constexpr auto O = BF::offset_pattern(g);
      articulated<S>& z = x[p];
      const mat3<S> a1 = turned_up(e, y.a), b1 = turned_up(e, y.b), c1 = turned_up(e, y.c);
      const vec f1 = e.up(y.f);
      z.f = z.f + f1, z.n = z.n + e.up(y.n);
      if constexpr (all_zero(O))
        z.a += a1, z.b += b1, z.c += c1;
      else {
        const mat3<S> tx = skew(bf.offset[g]), tc = tx * c1;
        z.a += a1 - b1 * tx + tx * b1.transpose() - tc * tx, z.b += b1 + tc, z.c += c1;
        z.n = z.n + cross3(bf.offset[g], f1);
      }
    }
  });
  std::array<vec, nf> aw, av;                                         // spatial accelerations
  aw[0] = zero, av[0] = base_acceleration<Sys, frame_at<JF, 0>>(ev);  // -g
  static_for<nf - 1>([&](auto i) {
    constexpr std::size_t g = i + 1, p = std::size_t(t.parent[g]);
    constexpr int r = t.speed[g];
    constexpr auto O = BF::offset_pattern(g);
    const auto& e = std::get<g>(bf.e);
    aw[g] = e.down(aw[p]) + cw[g];
    av[g] = (all_zero(O) ? e.down(av[p]) : e.down(av[p] + cross_along<O>(aw[p], bf.offset[g]))) + cv[g];
    if constexpr (r >= 0) {
      using F = frame_at<JF, g>;
      constexpr auto K = joint_axis_pattern<F>();
      const S a = (dn[r] - dot3(uw[r], aw[g]) - dot3(uv[r], av[g])) / dd[r];
      ud(Eigen::Index(r)) = a;
      aw[g] = add_along<K, onto::sum>(aw[g], a, joint_axis_in_frame<F, S>());
    }
  });
  return ok;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
