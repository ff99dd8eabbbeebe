// The mass matrix by composite bodies (the composite-rigid-body algorithm):
// Kane's M_rs = sum over items of m v_r . v_s + w_r . I . w_s, regrouped. In a
// system of joint form (joint_form.hpp) every item below the edge of u_s turns
// about the axis k_s through o_s, so its partial velocities are the screw
// (k_s, 0) about o_s in the body coordinates of that edge (body_frames.hpp) and
//   M_rs = (k_r, 0) . (Ic_s (k_s, 0)) carried from o_s to o_r,
// with Ic_s = (m, h, I_o) the spatial inertia of all items below the edge about
// o_s: the items' I_C + m (|c|^2 1 - c c), m c, accumulated from the leaves as
//   I_P += E I E^T + (2 t.h' + m |t|^2) 1 - (t h' + h' t) - m t t,  h_P += h' + m t,
// h' = E h. The column of u_s is the force (I_o k_s, k_s x h), carried up frame
// by frame (n -> E n + t x E f, f -> E f) and read along each axis above.
// A free joint (joint_form.hpp) reads its block from Ic about its origin o: I_o, the
// force h x (E^T r_j) of a translation along r_j, and m 1; a column arriving at its frame
// reads n and E f. Cost: O(n) to accumulate, O(depth) per column.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The pattern of k x h
constexpr std::array<entry, 3> crossed(const std::array<entry, 3>& k, const std::array<entry, 3>& h) {
  std::array<entry, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t a = (i + 1) % 3, b = (i + 2) % 3;
    const bool x =
        (k[a] != entry::zero && h[b] != entry::zero) || (k[b] != entry::zero && h[a] != entry::zero);
    out[i] = x ? entry::other : entry::zero;
  }
  return out;
}

// The force (n about o_F, f of pattern P) in F's components carried to the frames above F:
// M_rs = k_r . n there.
template <class JF, std::size_t F, std::array<entry, 3> P, class BF, class S, class Out>
KANE_ALWAYS_INLINE void column_up(const BF& bf, v3<S> n, v3<S> f, Out& M, Eigen::Index s) {
  static constexpr auto& t = JF::table;
  constexpr int p = t.parent[F];
  if constexpr (p > 0) {
    const auto& e = std::get<F>(bf.e);
    constexpr auto T = BF::offset_pattern(F);
    n = e.up(n);
    if constexpr (!all_zero(P)) {
      f = e.template up_along<P>(f);
      if constexpr (!all_zero(T)) n = n + cross_from<T>(bf.offset[F], f);
    }
    constexpr int r = t.speed[std::size_t(p)];
    if constexpr (r >= 0) {
      using R = frame_at<JF, std::size_t(p)>;
      const S x = dot_along<joint_axis_pattern<R>()>(n, joint_axis_in_frame<R, S>());
      M(Eigen::Index(r), s) = x, M(s, Eigen::Index(r)) = x;
    } else if constexpr (p == t.free) {  // u_1..3: n; u_4..6: E f
      const v3<S> fo = all_zero(P) ? v3<S>{S(0), S(0), S(0)} : std::get<std::size_t(p)>(bf.e).up(f);
      const std::array<S, 6> x{n.x, n.y, n.z, fo.x, fo.y, fo.z};
      for (std::size_t k = 0; k < 6; ++k) M(Eigen::Index(k), s) = x[k], M(s, Eigen::Index(k)) = x[k];
    }
    column_up<JF, std::size_t(p), BF::turned_pattern(F, P)>(bf, n, f, M, s);
  }
}

// Above this many speeds the columns are read in the root's components: the screws of the
// speeds S_r = (k_r, o_r x k_r) and each column's force (R n + o x R f, R f) once, then
// M_rs = S_r . F_s in a loop over the speeds above (11 operations an entry, code O(n));
// below, each column is carried up frame by frame, unrolled, with the axes' zeros known.
inline constexpr std::size_t unrolled_columns = 12;

template <class JF, class Ev>
struct root_screws {
  using S = typename Ev::scalar;
  std::array<v3<S>, JF::nf> origin;  // r^{O o_F}
  std::array<v3<S>, JF::n> k, m;     // S_r = (k_r, o_r x k_r)

  KANE_ALWAYS_INLINE root_screws(const body_frames<JF, Ev>& bf, const Ev& ev) {
    static constexpr auto& t = JF::table;
    origin[0] = {S(0), S(0), S(0)};
    static_for<JF::nf - 1>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t f = i + 1, p = std::size_t(t.parent[f]);
      using F = frame_at<JF, f>;
      if constexpr (all_zero(body_frames<JF, Ev>::offset_pattern(f)))
        origin[f] = origin[p];
      else if constexpr (p == 0)
        origin[f] = bf.offset[f];
      else
        origin[f] = origin[p] + to_root<frame_at<JF, p>>(bf.offset[f], ev);
      if constexpr (t.speed[f] >= 0) {
        constexpr std::size_t r = std::size_t(t.speed[f]);
        k[r] = to_root<F>(joint_axis_in_frame<F, S>(), ev);
        m[r] = cross3(origin[f], k[r]);
      } else if constexpr (int(f) == t.free)  // (b_i, o x b_i), (0, r_i)
        for (std::size_t i = 0; i < 3; ++i) {
          const v3<S> unit{S(i == 0), S(i == 1), S(i == 2)};
          k[i] = to_root<F>(unit, ev), m[i] = cross3(origin[f], k[i]);
          k[3 + i] = {S(0), S(0), S(0)}, m[3 + i] = unit;
        }
    });
  }
  // v (in F's components) in the root's
  template <class F>
  KANE_ALWAYS_INLINE static v3<S> to_root(const v3<S>& v, const Ev& ev) {
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return v;
    else {
      const auto a = ev.template axes<F>();
      return {a(0, 0) * v.x + a(0, 1) * v.y + a(0, 2) * v.z, a(1, 0) * v.x + a(1, 1) * v.y + a(1, 2) * v.z,
              a(2, 0) * v.x + a(2, 1) * v.y + a(2, 2) * v.z};
    }
  }
};

// Whether every speed is above or below every other: all of M is written.
template <class T>
constexpr bool on_one_path(const T& t) {
  std::size_t k = 0, n = t.parent_speed.size();
  for (std::size_t s = 0; s < n; ++s)
    for (int r = int(s); r >= 0; r = t.parent_speed[std::size_t(r)]) ++k;
  return k == n * (n + 1) / 2;
}

// M of the joint-form system Sys.
template <class JF, class Sys, class Ev, class Out>
KANE_ALWAYS_INLINE void composite_mass_matrix(const body_frames<JF, Ev>& bf, const Ev& ev, Out& M) {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  static constexpr auto& t = JF::table;
  constexpr std::size_t nf = JF::nf;
  std::array<composite_inertia<S>, nf> c;
  using known = known_inertias<JF, Sys, body_frames<JF, Ev>>;
  if constexpr (known::value)  // constants
    static_for_inline<nf>([&](auto f) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr composite_inertia<double> o = known::own[f];
      c[f] = {S(o.mass),
              {S(o.h.x), S(o.h.y), S(o.h.z)},
              {S(o.i[0]), S(o.i[1]), S(o.i[2]), S(o.i[3]), S(o.i[4]), S(o.i[5])}};
    });
  else {
    for (auto& x : c) x.mass = S(0), x.h = {S(0), S(0), S(0)}, x.i = {S(0), S(0), S(0), S(0), S(0), S(0)};
    [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      (
          [&]() KANE_ALWAYS_INLINE_LAMBDA {
            constexpr int f = t.item_frame[I];
            if constexpr ((is_particle<X> || is_body<X>)&&f > 0) {
              constexpr int p = t.item_point[I];
              const vec at = bf.template local<p, f>();
              constexpr auto C = body_frames<JF, Ev>::local_pattern(p, f);
              add_item_mass<X, C>(c[std::size_t(f)], at, ev);
            }
          }(),
          ...);
    }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  }
  if constexpr (!on_one_path(t)) M.setZero();  // entries off the tree's paths
  constexpr bool loop = JF::n > unrolled_columns;
  [[maybe_unused]] const auto screws = [&]() KANE_ALWAYS_INLINE_LAMBDA {
    if constexpr (loop)
      return root_screws<JF, Ev>(bf, ev);
    else
      return 0;
  }();
  // leaves first: c[f] is complete, its column, then into its parent
  static_for_inline<nf - 1>([&](auto j) KANE_ALWAYS_INLINE_LAMBDA {
    constexpr std::size_t f = nf - 1 - j;
    constexpr int s = t.speed[f];
    const composite_inertia<S>& x = c[f];
    if constexpr (s >= 0) {
      using F = frame_at<JF, f>;
      constexpr auto K = joint_axis_pattern<F>();
      const vec k = joint_axis_in_frame<F, S>();
      const vec n = symmetric_along<K>(x.i, k);
      M(Eigen::Index(s), Eigen::Index(s)) = dot_along<K>(n, k);
      if constexpr (!loop)
        column_up<JF, f, crossed(K, known::h_pattern[f])>(bf, n, cross_from<K>(k, x.h), M, Eigen::Index(s));
      else if constexpr (t.parent_speed[std::size_t(s)] >= 0) {
        using R = root_screws<JF, Ev>;
        const vec fw = R::template to_root<F>(cross_from<K>(k, x.h), ev);
        const vec nw = R::template to_root<F>(n, ev) + cross3(screws.origin[f], fw);
        for (int r = t.parent_speed[std::size_t(s)]; r >= 0; r = t.parent_speed[std::size_t(r)]) {
          const S e = dot3(screws.k[std::size_t(r)], nw) + dot3(screws.m[std::size_t(r)], fw);
          M(Eigen::Index(r), Eigen::Index(s)) = e, M(Eigen::Index(s), Eigen::Index(r)) = e;
        }
      }
    }
    if constexpr (int(f) == t.free) {  // I_o; (h x E^T r_j); m 1
      const auto& e = std::get<f>(bf.e);
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b) {
          M(Eigen::Index(a), Eigen::Index(b)) = x.i[sym_index[a][b]];
          M(Eigen::Index(3 + a), Eigen::Index(3 + b)) = a == b ? x.mass : S(0);
        }
      for (std::size_t j = 0; j < 3; ++j) {
        const vec hr = cross3(x.h, e.down(vec{S(j == 0), S(j == 1), S(j == 2)}));
        const std::array<S, 3> y{hr.x, hr.y, hr.z};
        for (std::size_t a = 0; a < 3; ++a)
          M(Eigen::Index(a), Eigen::Index(3 + j)) = y[a], M(Eigen::Index(3 + j), Eigen::Index(a)) = y[a];
      }
    }
    if constexpr (t.parent[f] > 0)
      c[std::size_t(t.parent[f])].template add<body_frames<JF, Ev>::offset_pattern(f), known::h_pattern[f]>(
          x, std::get<f>(bf.e), bf.offset[f]);
  });
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
