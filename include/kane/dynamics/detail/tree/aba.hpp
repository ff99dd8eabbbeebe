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
#include "kane/dynamics/detail/tree/frame_steps.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// M v and M^T v
template <class S>
KANE_ALWAYS_INLINE v3<S> times3(const m3<S>& m, const v3<S>& v) {
  return {dot3(m[0], v), dot3(m[1], v), dot3(m[2], v)};
}
template <class S>
KANE_ALWAYS_INLINE v3<S> times3_transposed(const m3<S>& m, const v3<S>& v) {
  return v.x * m[0] + v.y * m[1] + v.z * m[2];
}
// M^T k, k of pattern K
template <std::array<entry, 3> K, class S>
KANE_ALWAYS_INLINE v3<S> transposed_along(const m3<S>& m, const v3<S>& k) {
  return {dot_along<K>(v3<S>{m[0].x, m[1].x, m[2].x}, k), dot_along<K>(v3<S>{m[0].y, m[1].y, m[2].y}, k),
          dot_along<K>(v3<S>{m[0].z, m[1].z, m[2].z}, k)};
}
// M - x y^T / d, and the symmetric M - x x^T / d
template <class S>
KANE_ALWAYS_INLINE m3<S> minus_outer(const m3<S>& m, const v3<S>& x, const v3<S>& y, const S& inv) {
  return {m[0] - (inv * x.x) * y, m[1] - (inv * x.y) * y, m[2] - (inv * x.z) * y};
}
template <class S>
KANE_ALWAYS_INLINE sym3<S> minus_outer(const sym3<S>& m, const v3<S>& x, const S& inv) {
  const v3<S> y = inv * x;
  return {m[0] - x.x * y.x, m[1] - x.y * y.y, m[2] - x.z * y.z,
          m[3] - x.x * y.y, m[4] - x.y * y.z, m[5] - x.z * y.x};
}

template <class S>
struct articulated {
  sym3<S> a;  // [A B; B^T C]
  m3<S> b;
  sym3<S> c;
  v3<S> n, f;  // bias force
};

// [A B; B^T C] of the child, turned to the parent, moved by t (pattern O) to the parent's origin:
// C, B + [t] C, A - P - P^T - [t] C [t] with P = B [t].
template <std::array<entry, 3> O, class S>
KANE_ALWAYS_INLINE void add_moved(articulated<S>& z, const sym3<S>& a, const m3<S>& b, const sym3<S>& c,
                                  const v3<S>& t) {
  if constexpr (all_zero(O)) {
    z.a = z.a + a, z.b = z.b + b, z.c = z.c + c;
  } else {
    const v3<S> c0{c[0], c[3], c[5]}, c1{c[3], c[1], c[4]}, c2{c[5], c[4], c[2]};  // C's columns
    const v3<S> tc0 = cross_from<O>(t, c0), tc1 = cross_from<O>(t, c1), tc2 = cross_from<O>(t, c2);
    const m3<S> tc{v3<S>{tc0.x, tc1.x, tc2.x}, v3<S>{tc0.y, tc1.y, tc2.y}, v3<S>{tc0.z, tc1.z, tc2.z}};
    const m3<S> p{cross_from<O>(t, b[0]), cross_from<O>(t, b[1]), cross_from<O>(t, b[2])};     // -P's rows
    const m3<S> q{cross_from<O>(t, tc[0]), cross_from<O>(t, tc[1]), cross_from<O>(t, tc[2])};  // -[t]C[t]
    z.a = z.a + sym3<S>{a[0] + S(2) * p[0].x + q[0].x,   a[1] + S(2) * p[1].y + q[1].y,
                        a[2] + S(2) * p[2].z + q[2].z,   a[3] + p[0].y + p[1].x + q[0].y,
                        a[4] + p[1].z + p[2].y + q[1].z, a[5] + p[2].x + p[0].z + q[2].x};
    z.b = z.b + b + tc, z.c = z.c + c;
  }
}

// u' of the joint-form system Sys; false where an articulated inertia along a speed is not positive
// (a mask per lane for lanes).
template <class JF, class Sys, class Ev, class Out>
KANE_ALWAYS_INLINE auto articulated_accelerations(const body_frames<JF, Ev>& bf, const Ev& ev, Out& ud) {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  static constexpr auto& t = JF::table;
  constexpr std::size_t nf = JF::nf, n = JF::n;
  const frame_steps<JF, Ev> steps(bf);
  const auto step = [&](std::size_t g, auto&& f) KANE_ALWAYS_INLINE_LAMBDA { steps.at(g, f); };
  const vec zero{S(0), S(0), S(0)};
  std::array<vec, nf> w, v, cw, cv;
  std::array<articulated<S>, nf> x;
  std::array<vec, n> uw, uv;
  std::array<S, n> dd, dn;
  // each frame's own items: their inertias (a table of numbers where literals give them), their loads
  using known = known_inertias<JF, Sys, body_frames<JF, Ev>>;
  constexpr bool loaded = loads_below_root<JF, Sys>;
  std::array<composite_inertia<S>, known::value ? 1 : nf> rigid;
  if constexpr (!known::value) own_inertias<JF, Sys>(bf, ev, rigid);
  std::array<vec, loaded ? nf : 1> ff, fn;
  if constexpr (loaded) own_loads<JF, Sys>(bf, ev, ff, fn);
  w[0] = zero, v[0] = zero;
  // velocities, bias accelerations, and each frame's I = [i [h]; -[h] m 1] and p = v x* I v - f_ext
  for (std::size_t g = 1; g < nf; ++g)
    step(g, [&](const auto& e, auto KC, auto OC, const vec& kg) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr auto K = decltype(KC)::value;
      constexpr auto O = decltype(OC)::value;
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      const vec wp = e.down(w[p]);
      vec wg = wp, vg = all_zero(O) ? e.down(v[p]) : e.down(v[p] + cross_along<O>(w[p], bf.offset[g]));
      cw[g] = zero, cv[g] = zero;
      if (r >= 0) {
        const S u = joint_rate<1>(ev, std::size_t(r));
        wg = add_along<K, onto::sum>(wp, u, kg);
        cw[g] = u * cross_along<K>(wg, kg), cv[g] = u * cross_along<K>(vg, kg);
      }
      w[g] = wg, v[g] = vg;
      const composite_inertia<S> q = [&] {
        if constexpr (known::value) {
          const composite_inertia<double>& o = known::own[g];
          return composite_inertia<S>{S(o.mass),
                                      {S(o.h.x), S(o.h.y), S(o.h.z)},
                                      {S(o.i[0]), S(o.i[1]), S(o.i[2]), S(o.i[3]), S(o.i[4]), S(o.i[5])}};
        } else
          return rigid[g];
      }();
      articulated<S>& y = x[g];
      y.a = q.i;
      y.b = {vec{S(0), -q.h.z, q.h.y}, vec{q.h.z, S(0), -q.h.x}, vec{-q.h.y, q.h.x, S(0)}};  // [h]
      y.c = {q.mass, q.mass, q.mass, S(0), S(0), S(0)};
      const vec hh = sym_times(q.i, wg) + cross3(q.h, vg), ll = q.mass * vg - cross3(q.h, wg);
      y.n = cross3(wg, hh) + cross3(vg, ll), y.f = cross3(wg, ll);
      if constexpr (loaded) y.n = y.n + fn[g], y.f = y.f + ff[g];
    });
  auto ok = lane_traits<S>::truth(true);
  for (std::size_t g = nf - 1; g > 0; --g)  // leaves first
    step(g, [&](const auto& e, auto KC, auto OC, const vec& kg) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr auto K = decltype(KC)::value;
      constexpr auto O = decltype(OC)::value;
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      articulated<S>& y = x[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        uw[j] = symmetric_along<K>(y.a, kg), uv[j] = transposed_along<K>(y.b, kg);
        dd[j] = dot_along<K>(uw[j], kg), dn[j] = -dot_along<K>(y.n, kg);
        ok = ok && dd[j] > S(0);
        if (p > 0) {
          const S inv = S(1) / dd[j];
          y.a = minus_outer(y.a, uw[j], inv), y.b = minus_outer(y.b, uw[j], uv[j], inv);
          y.c = minus_outer(y.c, uv[j], inv);
          const S sj = dn[j] * inv;
          y.n = y.n + sym_times(y.a, cw[g]) + times3(y.b, cv[g]) + sj * uw[j];
          y.f = y.f + times3_transposed(y.b, cw[g]) + sym_times(y.c, cv[g]) + sj * uv[j];
        }
      }
      if (p > 0) {
        articulated<S>& z = x[p];
        const vec f1 = e.up(y.f);
        z.f = z.f + f1, z.n = z.n + e.up(y.n);
        add_moved<O>(z, e.up(y.a), e.up(y.b), e.up(y.c), bf.offset[g]);
        if constexpr (!all_zero(O)) z.n = z.n + cross_from<O>(bf.offset[g], f1);
      }
    });
  std::array<vec, nf> aw, av;                                         // spatial accelerations
  aw[0] = zero, av[0] = base_acceleration<Sys, frame_at<JF, 0>>(ev);  // -g
  for (std::size_t g = 1; g < nf; ++g)
    step(g, [&](const auto& e, auto KC, auto OC, const vec& kg) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr auto K = decltype(KC)::value;
      constexpr auto O = decltype(OC)::value;
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      aw[g] = e.down(aw[p]) + cw[g];
      av[g] = (all_zero(O) ? e.down(av[p]) : e.down(av[p] + cross_along<O>(aw[p], bf.offset[g]))) + cv[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        const S a = (dn[j] - dot3(uw[j], aw[g]) - dot3(uv[j], av[g])) / dd[j];
        ud(Eigen::Index(j)) = a;
        aw[g] = add_along<K, onto::sum>(aw[g], a, kg);
      }
    });
  return ok;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
