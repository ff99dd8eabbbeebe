// Derivatives of inverse dynamics by q and u (by u' they are M), in two passes over a system of
// joint form (after Carpentier and Mansard, RSS 2018). All spatial vectors are in the root's
// components about its origin O: a speed's partial velocities are the screw S = (k, p x k) of
// its axis k through p. A change of q_j turns every item below the edge of u_j about S_j, and
// with it every quantity of those items (S_j x for motions, S_j x* for forces), except what
// they receive from above: v^- and a^-, the velocity and acceleration of the edge's parent.
// Outward, from a_O = (0, -g):
//   v = v^- + S u,  a = a^- + S u' + dV u,  dV = v^- x S,  dA = a^- x S + v^- x dV;
//   per frame Y = (m, h, I about O), the momentum l = Y v, f = Y a + v x* l - f_ext and
//   B x = (Z x_w + x_w x l_w, 2 x_w x l_v), Z = [w]I - I[w] + 2 (h.v) 1 - h v^T - v h^T,
//   so that df/dq_j = S_j x* f + Y dA_j + B dV_j and df/du_j = 2 Y dV_j + B S_j.
// Inward, with Y, B and F summed over the items below each edge (S_j x* cancels in S . F):
//   tau_r = S_r . F_r,  M_rj = (Y_r S_r) . S_j,
//   dtau_r/dq_j = (Y_r S_r) . dA_j + (B_r^T S_r) . dV_j,  dtau_r/du_j = (Y_r S_r) . 2 dV_j +
//   (B_r^T S_r) . S_j for u_j at or above u_r, and dtau_j/dq_r = S_j . (Y_r dA_r + B_r dV_r +
//   S_r x* F_r), dtau_j/du_r = S_j . (2 Y_r dV_r + B_r S_r) for u_j above it.
// Loads must turn with the bodies they act on (steady_loads). Cost: O(n) and 36 products a pair.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"
#include "kane/dynamics/detail/tree/frame_steps.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"
#include "kane/dynamics/detail/tree/spatial.hpp"
#include "kane/dynamics/detail/tree/steady_loads.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The passes over the joint-form system Sys; each frame's own items, then u', then the sums.
template <class JF, class Sys, class Ev>
struct tree_partials {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  using BF = body_frames<JF, Ev>;
  static constexpr auto& t = JF::table;
  static constexpr std::size_t nf = JF::nf, n = JF::n;

  std::array<m3<S>, nf> rot;                    // R of each frame, by columns
  std::array<vec, nf> at;                       // its origin from O
  std::array<composite_inertia<S>, nf> own, y;  // each frame's items, and those below it
  std::array<spatial<S>, nf> load, v, a, f;     // -f_ext about O; velocity, acceleration, force
  std::array<variation<S>, nf> b;
  std::array<spatial<S>, n> screw, dv, da;

  // R, the origins, the screws, the items' inertias and loads about O.
  KANE_ALWAYS_INLINE tree_partials(const BF& bf, const Ev& ev) {
    const vec zero{S(0), S(0), S(0)};
    const frame_steps<JF, Ev> steps(bf);
    rot[0] = {vec{S(1), S(0), S(0)}, vec{S(0), S(1), S(0)}, vec{S(0), S(0), S(1)}}, at[0] = zero;
    own_inertias<JF, Sys>(bf, ev, own);
    std::array<vec, nf> ff, fn;  // -f_ext about o, in the frame's components
    own_loads<JF, Sys>(bf, ev, ff, fn);
    for (std::size_t g = 1; g < nf; ++g)
      steps.at(g, [&](const auto& e, auto, auto OC, const vec& kg) KANE_ALWAYS_INLINE_LAMBDA {
        constexpr auto O = decltype(OC)::value;
        const auto p = std::size_t(t.parent[g]);
        const int r = t.speed[g];
        rot[g] = {by_columns(rot[p], e.up(vec{S(1), S(0), S(0)})),
                  by_columns(rot[p], e.up(vec{S(0), S(1), S(0)})),
                  by_columns(rot[p], e.up(vec{S(0), S(0), S(1)}))};
        at[g] = all_zero(O) ? at[p] : at[p] + by_columns(rot[p], bf.offset[g]);
        if (r >= 0) {
          const vec k = by_columns(rot[g], kg);
          screw[std::size_t(r)] = {k, cross3(at[g], k)};
        }
        own[g] = about_root(own[g], rot[g], at[g]);
        const vec fw = by_columns(rot[g], ff[g]);
        load[g] = {by_columns(rot[g], fn[g]) + cross3(at[g], fw), fw};
      });
    v[0] = {zero, zero}, a[0] = {zero, base_acceleration<Sys, frame_at<JF, 0>>(ev)};
  }
  // Velocities, accelerations at the rates ud, dV, dA, f and B of each frame's items.
  template <class Rates>
  KANE_ALWAYS_INLINE void outward(const Ev& ev, const Rates& ud) {
    for (std::size_t g = 1; g < nf; ++g) {
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      v[g] = v[p], a[g] = a[p];
      if (r >= 0) {
        const auto j = std::size_t(r);
        const spatial<S>& s = screw[j];
        const S u = joint_rate<1>(ev, j);
        dv[j] = cross_motion(v[p], s), da[j] = cross_motion(a[p], s) + cross_motion(v[p], dv[j]);
        v[g] = v[p] + u * s, a[g] = a[p] + S(ud(Eigen::Index(j))) * s + u * dv[j];
      }
      const spatial<S> l = times(own[g], v[g]);
      f[g] = times(own[g], a[g]) + cross_force(v[g], l) + load[g];
      b[g] = variation_of(own[g], v[g], l);
    }
  }
  // Speeds on one path from the root: every pair of speeds is related, each entry written.
  static constexpr bool one_path = [] {
    for (std::size_t r = 0; r < n; ++r)
      if (t.parent_speed[r] != int(r) - 1) return false;
    return true;
  }();
  // tau, M (when Mass), dtau/dq and dtau/du.
  template <bool Mass = true, class Tau, class Square>
  KANE_ALWAYS_INLINE void inward(Tau& tau, Square& m, Square& dq, Square& du) {
    y = own;
    if constexpr (!one_path) {
      dq.setZero(), du.setZero();
      if constexpr (Mass) m.setZero();
    }
    for (std::size_t g = nf - 1; g > 0; --g) {
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      if (r >= 0) {
        const auto k = Eigen::Index(r);
        const spatial<S>& s = screw[std::size_t(r)];
        const spatial<S> ys = times(y[g], s);
        const vec bs = b[g].transposed_times(s);
        const spatial<S> fq =
            times(y[g], da[std::size_t(r)]) + b[g].times(dv[std::size_t(r)]) + cross_force(s, f[g]);
        const spatial<S> fu = S(2) * times(y[g], dv[std::size_t(r)]) + b[g].times(s);
        tau(k) = dot6(s, f[g]);
        for (int c = r; c >= 0; c = t.parent_speed[std::size_t(c)]) {
          const auto j = std::size_t(c);
          const auto l = Eigen::Index(c);
          if constexpr (Mass) m(k, l) = m(l, k) = dot6(ys, screw[j]);
          dq(k, l) = dot6(ys, da[j]) + dot3(bs, dv[j].w);
          du(k, l) = S(2) * dot6(ys, dv[j]) + dot3(bs, screw[j].w);
          if (c != r) dq(l, k) = dot6(screw[j], fq), du(l, k) = dot6(screw[j], fu);
        }
      }
      if (p > 0) add_to(y[p], y[g]), add_to(b[p], b[g]), f[p] = f[p] + f[g];
    }
  }
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
