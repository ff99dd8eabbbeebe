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
// Cost: O(n) to accumulate, O(depth) per column.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/body_frames.hpp"
#include "kane/dynamics/terms.hpp"

namespace kane::detail {

template <class S>
struct composite_inertia {
  S mass;
  v3<S> h;
  sym3<S> i;  // about the frame's origin

  // m at c (of pattern C) with the inertia ic about c (none: a particle)
  template <std::array<entry, 3> C, bool Inertia>
  KANE_ALWAYS_INLINE void add_mass(const S& m, const v3<S>& c, const sym3<S>& ic) {
    constexpr auto mp = scaled_pattern(C);
    const v3<S> mc{product<entry::other, C[0]>(m, c.x), product<entry::other, C[1]>(m, c.y),
                   product<entry::other, C[2]>(m, c.z)};
    mass = mass + m;
    h = {plus_product<entry::one, mp[0]>(h.x, S(1), mc.x), plus_product<entry::one, mp[1]>(h.y, S(1), mc.y),
         plus_product<entry::one, mp[2]>(h.z, S(1), mc.z)};
    sym3<S> j = i;
    if constexpr (Inertia)
      for (std::size_t k = 0; k < 6; ++k) j[k] = j[k] + ic[k];
    i[0] = plus_product<mp[2], C[2]>(plus_product<mp[1], C[1]>(j[0], mc.y, c.y), mc.z, c.z);
    i[1] = plus_product<mp[0], C[0]>(plus_product<mp[2], C[2]>(j[1], mc.z, c.z), mc.x, c.x);
    i[2] = plus_product<mp[1], C[1]>(plus_product<mp[0], C[0]>(j[2], mc.x, c.x), mc.y, c.y);
    i[3] = minus_product<mp[0], C[1]>(j[3], mc.x, c.y);
    i[4] = minus_product<mp[1], C[2]>(j[4], mc.y, c.z);
    i[5] = minus_product<mp[2], C[0]>(j[5], mc.z, c.x);
  }
  // o's inertia, turned by E and moved by t (of pattern T):
  // I += E I E^T + (2 t.h' + m |t|^2) 1 - (t h' + h' t) - m t t, h += h' + m t
  // (o.h of pattern H)
  template <std::array<entry, 3> T, std::array<entry, 3> H, class Turn>
  KANE_ALWAYS_INLINE void add(const composite_inertia& o, const Turn& e, const v3<S>& t) {
    constexpr auto h1p = Turn::turned(H);
    const v3<S> h1 = e.template up_along<H>(o.h);
    const sym3<S> i1 = e.up(o.i);
    mass = mass + o.mass;
    for (std::size_t k = 0; k < 6; ++k) i[k] = i[k] + i1[k];
    h = {plus_product<entry::one, h1p[0]>(h.x, S(1), h1.x), plus_product<entry::one, h1p[1]>(h.y, S(1), h1.y),
         plus_product<entry::one, h1p[2]>(h.z, S(1), h1.z)};
    if constexpr (!all_zero(T)) {
      constexpr auto mp = scaled_pattern(T);
      const v3<S> mt{product<entry::other, T[0]>(o.mass, t.x), product<entry::other, T[1]>(o.mass, t.y),
                     product<entry::other, T[2]>(o.mass, t.z)};
      const v3<S> g = {S(2) * h1.x + mt.x, S(2) * h1.y + mt.y, S(2) * h1.z + mt.z};  // 2 h' + m t
      const S d = dot_along<T>(g, t);
      h = {plus_product<entry::one, mp[0]>(h.x, S(1), mt.x), plus_product<entry::one, mp[1]>(h.y, S(1), mt.y),
           plus_product<entry::one, mp[2]>(h.z, S(1), mt.z)};
      i[0] = minus_product<T[0], entry::other>(i[0] + d, t.x, g.x);
      i[1] = minus_product<T[1], entry::other>(i[1] + d, t.y, g.y);
      i[2] = minus_product<T[2], entry::other>(i[2] + d, t.z, g.z);
      // -(t h' + h' t) - m t t = -(t g + h' t - ...): off-diagonal t_a h'_b + h'_a t_b + m t_a t_b
      i[3] = minus_product<T[1], entry::other>(minus_product<T[0], entry::other>(i[3], t.x, h1.y + mt.y), t.y,
                                               h1.x);
      i[4] = minus_product<T[2], entry::other>(minus_product<T[1], entry::other>(i[4], t.y, h1.z + mt.z), t.z,
                                               h1.y);
      i[5] = minus_product<T[0], entry::other>(minus_product<T[2], entry::other>(i[5], t.z, h1.x + mt.x), t.x,
                                               h1.z);
    }
  }
};

// The inertia of each frame's own items about its origin, in its components, when every number
// is known at compile time (literal masses, inertias and positions): composites start from constants.
template <class X>
constexpr bool known_item() {
  if constexpr (is_body<X>) {
    using I = typename X::inertia_type;
    using C = std::remove_cvref_t<decltype(I::components)>;
    return known_scalar<std::remove_cv_t<decltype(X::mass)>>() &&
           std::is_same_v<typename I::frame, typename X::frame> &&
           known_scalar<std::tuple_element_t<0, C>>() && known_scalar<std::tuple_element_t<1, C>>() &&
           known_scalar<std::tuple_element_t<2, C>>() && known_scalar<std::tuple_element_t<3, C>>() &&
           known_scalar<std::tuple_element_t<4, C>>() && known_scalar<std::tuple_element_t<5, C>>();
  } else if constexpr (is_particle<X>)
    return known_scalar<std::remove_cv_t<decltype(X::mass)>>();
  else
    return true;
}
// m and I_C (11 22 33 12 23 31) of a particle or a body known at compile time; m = -1 for
// other items
template <class X>
constexpr std::array<double, 7> known_mass() {
  if constexpr ((is_particle<X> || is_body<X>)&&known_item<X>()) {
    std::array<double, 7> out{known_value(X::mass)};
    if constexpr (is_body<X>) {
      constexpr auto c = X::inertia_type::components;
      out = {out[0],
             known_value(std::get<0>(c)),
             known_value(std::get<1>(c)),
             known_value(std::get<2>(c)),
             known_value(std::get<3>(c)),
             known_value(std::get<4>(c)),
             known_value(std::get<5>(c))};
    }
    return out;
  } else
    return {-1, 0, 0, 0, 0, 0, 0};
}
template <class XL>
struct mass_facts;
template <class... X>
struct mass_facts<list<X...>> {
  static constexpr bool known = (known_item<X>() && ...);
  static constexpr std::array<std::array<double, 7>, sizeof...(X)> value{known_mass<X>()...};
};
template <class JF, class Sys, class BF>
struct known_inertias {
  static constexpr auto& t = JF::table;
  using masses = mass_facts<typename Sys::items>;
  static constexpr bool value = BF::known_positions && masses::known;
  static constexpr auto own = [] {
    std::array<composite_inertia<double>, JF::nf> out{};
    for (auto& x : out) x = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}};
    for (std::size_t k = 0; k < masses::value.size(); ++k) {
      const int f = t.item_frame[k];
      const auto& mi = masses::value[k];
      if (!value || f <= 0 || mi[0] < 0) continue;
      const double m = mi[0];
      const auto c = BF::known_local(t.item_point[k], f);
      composite_inertia<double>& o = out[std::size_t(f)];
      o.mass += m, o.h = {o.h.x + m * c[0], o.h.y + m * c[1], o.h.z + m * c[2]};
      o.i[0] += mi[1] + m * (c[1] * c[1] + c[2] * c[2]), o.i[1] += mi[2] + m * (c[2] * c[2] + c[0] * c[0]);
      o.i[2] += mi[3] + m * (c[0] * c[0] + c[1] * c[1]), o.i[3] += mi[4] - m * c[0] * c[1];
      o.i[4] += mi[5] - m * c[1] * c[2], o.i[5] += mi[6] - m * c[2] * c[0];
    }
    return out;
  }();
  // The pattern of each frame's composite first moment h (all other where not known).
  static constexpr auto h_pattern = [] {
    std::array<std::array<entry, 3>, JF::nf> out{};
    for (std::size_t f = 0; f < JF::nf; ++f)
      out[f] = value ? std::array<entry, 3>{own[f].h.x == 0 ? entry::zero : entry::other,
                                            own[f].h.y == 0 ? entry::zero : entry::other,
                                            own[f].h.z == 0 ? entry::zero : entry::other}
                     : std::array<entry, 3>{entry::other, entry::other, entry::other};
    std::array<double, JF::nf> mass{};
    for (std::size_t f = 0; f < JF::nf; ++f) mass[f] = value ? own[f].mass : 1;
    for (std::size_t f = JF::nf - 1; f > 0; --f) {  // leaves first
      const int p = t.parent[f];
      if (p <= 0) continue;
      const auto turned = BF::turned_pattern(f, out[f]), offset = BF::offset_pattern(f);
      for (std::size_t i = 0; i < 3; ++i)
        if (turned[i] != entry::zero || (mass[f] != 0 && offset[i] != entry::zero))
          out[std::size_t(p)][i] = entry::other;
      mass[std::size_t(p)] += mass[f];
    }
    return out;
  }();
};

// The inertia of body X about its centre in the components of its frame.
template <class X, class Ev>
KANE_ALWAYS_INLINE sym3<typename Ev::scalar> body_inertia(const Ev& ev) {
  using S = typename Ev::scalar;
  using I = typename X::inertia_type;
  sym3<S> o;
  if constexpr (std::is_same_v<typename I::frame, typename X::frame>) {
    static_for<6>([&](auto k) { o[k] = S(eval_scalar(std::get<k>(I::components), ev)); });
  } else {  // fixed in the body, or the same in both (a wheel): A^T (I in the root) A
    const Eigen::Matrix<S, 3, 3> a = ev.template axes<typename X::frame>();
    const Eigen::Matrix<S, 3, 3> r = a.transpose() * inertia_in_root<I>(ev) * a;
    o = {r(0, 0), r(1, 1), r(2, 2), r(0, 1), r(1, 2), r(2, 0)};
  }
  return o;
}

template <class JF, std::size_t F>
using frame_at = typename at<typename JF::frame_list, F>::type;

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
    static_for<JF::nf - 1>([&](auto i) {
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
    static_for<nf>([&](auto f) {
      constexpr composite_inertia<double> o = known::own[f];
      c[f] = {S(o.mass),
              {S(o.h.x), S(o.h.y), S(o.h.z)},
              {S(o.i[0]), S(o.i[1]), S(o.i[2]), S(o.i[3]), S(o.i[4]), S(o.i[5])}};
    });
  else {
    for (auto& x : c) x.mass = S(0), x.h = {S(0), S(0), S(0)}, x.i = {S(0), S(0), S(0), S(0), S(0), S(0)};
    [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
      (
          [&] {
            constexpr int f = t.item_frame[I];
            if constexpr ((is_particle<X> || is_body<X>)&&f > 0) {
              constexpr int p = t.item_point[I];
              const vec at = bf.template local<p, f>();
              constexpr auto C = body_frames<JF, Ev>::local_pattern(p, f);
              if constexpr (is_body<X>)
                c[std::size_t(f)].template add_mass<C, true>(S(eval_scalar(X::mass, ev)), at,
                                                             body_inertia<X>(ev));
              else
                c[std::size_t(f)].template add_mass<C, false>(S(eval_scalar(X::mass, ev)), at, {});
            }
          }(),
          ...);
    }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  }
  if constexpr (!on_one_path(t)) M.setZero();  // entries off the tree's paths
  constexpr bool loop = JF::n > unrolled_columns;
  [[maybe_unused]] const auto screws = [&] {
    if constexpr (loop)
      return root_screws<JF, Ev>(bf, ev);
    else
      return 0;
  }();
  static_for<nf - 1>([&](auto j) {  // leaves first: c[f] is complete, its column, then into its parent
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
    if constexpr (t.parent[f] > 0)
      c[std::size_t(t.parent[f])].template add<body_frames<JF, Ev>::offset_pattern(f), known::h_pattern[f]>(
          x, std::get<f>(bf.e), bf.offset[f]);
  });
}

}  // namespace kane::detail
