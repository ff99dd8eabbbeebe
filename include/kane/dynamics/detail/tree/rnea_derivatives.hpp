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
// A free joint's rows and columns: free_joint_partials.hpp.
// Loads must turn with the bodies they act on (steady_loads). Cost: O(n) and 36 products a pair.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/packet.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"
#include "kane/dynamics/detail/tree/frame_steps.hpp"
#include "kane/dynamics/detail/tree/free_joint_partials.hpp"
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
  static constexpr bool loaded = loads_below_root<JF, Sys>;

  std::array<m3<S>, nf> rot;                 // R of each frame, by columns
  std::array<vec, nf> at;                    // its origin from O
  std::array<composite_inertia<S>, nf> own;  // each frame's items; inward: and those below it
  std::array<spatial<S>, nf> load, v, a, f;  // -f_ext about O; velocity, acceleration, force
  std::array<variation<S>, nf> b;
  std::array<spatial<S>, n> screw, dv, da;
  static constexpr bool floating = t.free >= 0;
  std::array<spatial<S>, floating ? 3 : 0> turned;  // v_w x S_j of the free joint

  // R, the origins, the screws, the items' inertias and loads about O.
  KANE_ALWAYS_INLINE tree_partials(const BF& bf, const Ev& ev) {
    const vec zero{S(0), S(0), S(0)};
    const frame_steps<JF, Ev> steps(bf);
    rot[0] = {vec{S(1), S(0), S(0)}, vec{S(0), S(1), S(0)}, vec{S(0), S(0), S(1)}}, at[0] = zero;
    own_inertias<JF, Sys>(bf, ev, own);
    std::array<vec, nf> ff, fn;  // -f_ext about o, in the frame's components
    if constexpr (loaded) own_loads<JF, Sys>(bf, ev, ff, fn);
    for (std::size_t g = 1; g < nf; ++g)
      steps.at(g, [&](const auto& e, auto, auto OC, const vec& kg) KANE_ALWAYS_INLINE_LAMBDA {
        constexpr auto O = decltype(OC)::value;
        constexpr int A = std::remove_cvref_t<decltype(e)>::axis;
        const auto p = std::size_t(t.parent[g]);
        const int r = t.speed[g];
        rot[g] = e.after(rot[p]);
        at[g] = all_zero(O) ? at[p] : at[p] + by_columns(rot[p], bf.offset[g]);
        if (r >= 0) {
          vec k;
          if constexpr (A >= 0)
            k = rot[g][std::size_t(A)];  // the turn's axis: a column of R
          else
            k = by_columns(rot[g], kg);
          screw[std::size_t(r)] = {k, cross3(at[g], k)};
        }
        own[g] = about_root(own[g], rot[g], at[g]);
        if constexpr (loaded) {
          const vec fw = by_columns(rot[g], ff[g]);
          load[g] = {by_columns(rot[g], fn[g]) + cross3(at[g], fw), fw};
        }
      });
    if constexpr (floating) {  // (b_i, p x b_i), (0, r_i)
      constexpr auto g = std::size_t(t.free);
      for (std::size_t i = 0; i < 3; ++i) {
        const vec& k = rot[g][i];
        screw[i] = {k, cross3(at[g], k)};
        screw[3 + i] = {zero, vec{S(i == 0), S(i == 1), S(i == 2)}};
      }
    }
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
      } else if constexpr (floating) {
        if (g == std::size_t(t.free)) free_outward(*this, ev, ud, g);
      }
      const spatial<S> l = times(own[g], v[g]);
      f[g] = times(own[g], a[g]) + cross_force(v[g], l);
      if constexpr (loaded) f[g] = f[g] + load[g];
      b[g] = variation_of(own[g], v[g], l);
    }
  }
  // Speeds on one path from the root: every pair of speeds is related, each entry written.
  static constexpr bool one_path = [] {
    for (std::size_t r = 0; r < n; ++r)
      if (t.parent_speed[r] != int(r) - 1) return false;
    return true;
  }();
  // From this many speeds on one path, the columns of the derivatives go in packets (column).
  static constexpr std::size_t packed_from = 12;
  // Up to this many frames the inward pass is unrolled.
  static constexpr std::size_t unrolled_frames = 8;
  static constexpr bool packed = one_path && n >= packed_from && !floating;
  // tau, M (when Mass), dtau/dq and dtau/du; own summed in place, once.
  template <bool Mass = true, class Tau, class Square>
  KANE_ALWAYS_INLINE void inward(Tau& tau, Square& m, Square& dq, Square& du) {
    std::array<composite_inertia<S>, nf>& y = own;
    if constexpr (!one_path) {
      dq.setZero(), du.setZero();
      if constexpr (Mass) m.setZero();
    }
    [[maybe_unused]] std::array<std::array<S, n>, 9> ysb;  // packed: Y S and B^T S of each speed
    [[maybe_unused]] std::array<std::array<S, n>, 6> sc;   // and S, by component
    if constexpr (packed)
      for (std::size_t j = 0; j < n; ++j) put(sc, j, screw[j]);
    const auto step = [&](std::size_t g) KANE_ALWAYS_INLINE_LAMBDA {
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
        if constexpr (packed) {
          put(ysb, std::size_t(r), ys);
          ysb[6][std::size_t(r)] = bs.x, ysb[7][std::size_t(r)] = bs.y, ysb[8][std::size_t(r)] = bs.z;
          column<Mass>(std::size_t(r), fq, fu, m, dq, du, sc, ysb);
        } else
#pragma GCC unroll 16
          for (int c = r; c >= 0; c = t.parent_speed[std::size_t(c)]) {
            const auto j = std::size_t(c);
            const auto l = Eigen::Index(c);
            if constexpr (Mass) m(k, l) = m(l, k) = dot6(ys, screw[j]);
            dq(k, l) = dot6(ys, da[j]) + dot3(bs, dv[j].w);
            du(k, l) = S(2) * dot6(ys, dv[j]) + dot3(bs, screw[j].w);
            if constexpr (floating)
              if (j < 3) du(k, l) += dot6(ys, turned[j]);
            if (c != r) dq(l, k) = dot6(screw[j], fq), du(l, k) = dot6(screw[j], fu);
          }
      } else if constexpr (floating) {
        if (g == std::size_t(t.free)) free_inward<Mass>(*this, g, tau, m, dq, du);
      }
      if (p > 0) add_to(y[p], y[g]), add_to(b[p], b[g]), f[p] = f[p] + f[g];
    };
    if constexpr (nf <= unrolled_frames)  // leaves first, unrolled: the tree's indices fold
      static_for<nf - 1>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { step(nf - 1 - i); });
    else
      for (std::size_t g = nf - 1; g > 0; --g) step(g);
    if constexpr (packed && Mass)
      for (Eigen::Index c = 1; c < Eigen::Index(n); ++c)
        for (Eigen::Index r = 0; r < c; ++r) m(r, c) = m(c, r);
  }

 private:
  template <std::size_t N>
  static void put(std::array<std::array<S, n>, N>& to, std::size_t j, const spatial<S>& x) {
    to[0][j] = x.w.x, to[1][j] = x.w.y, to[2][j] = x.w.z, to[3][j] = x.v.x, to[4][j] = x.v.y,
    to[5][j] = x.v.z;
  }
  // a_0 x_0 + ... for packets x of V rows from k; the coefficients as packets when V = W
  template <std::size_t N, std::size_t V, std::size_t R, class C>
  KANE_ALWAYS_INLINE static packet<S, V> sum(const std::array<std::array<S, n>, R>& x, std::size_t k,
                                             const C& a) {
    static_assert(N <= R);
    packet<S, V> out = load_packet<V>(&x[0][k]) * a[0];
    static_for_inline<N - 1>(
        [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { out += load_packet<V>(&x[i + 1][k]) * a[i + 1]; });
    return out;
  }
  // Column r of one path, its rows contiguous (column-major), W at a time:
  // rows k >= r (the speeds below, summed): dq = Y_k S_k . da_r + B_k^T S_k . dv_r.w,
  // du = Y_k S_k . 2 dv_r + B_k^T S_k . S_r.w, M = Y_k S_k . S_r; rows l < r: S_l . fq_r, S_l . fu_r.
  template <bool Mass, class Square>
  KANE_ALWAYS_INLINE void column(std::size_t r, const spatial<S>& fq, const spatial<S>& fu, Square& m,
                                 Square& dq, Square& du, const std::array<std::array<S, n>, 6>& sc,
                                 const std::array<std::array<S, n>, 9>& ysb) const {
    static_assert(!Square::IsRowMajor);
    // packets of at most 32 bytes: AVX-512's 64 ran slower over the rows just written
    constexpr std::size_t W = packet_width<S> * sizeof(S) > 32 ? 32 / sizeof(S) : packet_width<S>;
    const spatial<S>&s = screw[r], &va = da[r], &vv = dv[r];
    const S two(2);
    const std::array<S, 9> aq{va.w.x, va.w.y, va.w.z, va.v.x, va.v.y, va.v.z, vv.w.x, vv.w.y, vv.w.z},
        au{two * vv.w.x, two * vv.w.y, two * vv.w.z, two * vv.v.x, two * vv.v.y,
           two * vv.v.z, s.w.x,        s.w.y,        s.w.z};
    const std::array<S, 6> am{s.w.x, s.w.y, s.w.z, s.v.x, s.v.y, s.v.z},
        fqa{fq.w.x, fq.w.y, fq.w.z, fq.v.x, fq.v.y, fq.v.z},
        fua{fu.w.x, fu.w.y, fu.w.z, fu.v.x, fu.v.y, fu.v.z};
    const auto spread = [](const auto& a) {  // the coefficients as packets
      std::array<packet<S, W>, std::tuple_size_v<std::remove_cvref_t<decltype(a)>>> p;
      for (std::size_t i = 0; i < p.size(); ++i) p[i] = splat<W>(a[i]);
      return p;
    };
    const auto pq = spread(aq), pu = spread(au);
    const auto pm = spread(am), pfq = spread(fqa), pfu = spread(fua);
    S *q = &dq(0, Eigen::Index(r)), *u = &du(0, Eigen::Index(r)), *mm = &m(0, Eigen::Index(r));
    const auto below = [&](std::size_t k, auto v, const auto& cq, const auto& cu, const auto& cm)
                           KANE_ALWAYS_INLINE_LAMBDA {
                             constexpr std::size_t V = decltype(v)::value;
                             store_packet<V>(sum<9, V>(ysb, k, cq), q + k);
                             store_packet<V>(sum<9, V>(ysb, k, cu), u + k);
                             if constexpr (Mass) store_packet<V>(sum<6, V>(ysb, k, cm), mm + k);
                           };
    const auto above = [&](std::size_t l, auto v, const auto& cq, const auto& cu) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t V = decltype(v)::value;
      store_packet<V>(sum<6, V>(sc, l, cq), q + l);
      store_packet<V>(sum<6, V>(sc, l, cu), u + l);
    };
    // the coefficients for packets of V: spread above, as numbers for 1, spread here for the rest
    const auto of = [&](auto v, const auto& wide, const auto& one) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t V = decltype(v)::value;
      if constexpr (V == W)
        return wide;
      else if constexpr (V == 1)
        return one;
      else {
        std::array<packet<S, V>, std::tuple_size_v<std::remove_cvref_t<decltype(one)>>> p;
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = splat<V>(one[i]);
        return p;
      }
    };
    in_packets<W>(r, n, [&](std::size_t k, auto v) KANE_ALWAYS_INLINE_LAMBDA {
      below(k, v, of(v, pq, aq), of(v, pu, au), of(v, pm, am));
    });
    in_packets<W>(0, r, [&](std::size_t l, auto v) KANE_ALWAYS_INLINE_LAMBDA {
      above(l, v, of(v, pfq, fqa), of(v, pfu, fua));
    });
  }
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
