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

  KANE_ALWAYS_INLINE void add_mass(const S& m, const v3<S>& c, const sym3<S>& ic) {
    const v3<S> mc = m * c;
    mass = mass + m, h = h + mc;
    i[0] = i[0] + ic[0] + mc.y * c.y + mc.z * c.z, i[1] = i[1] + ic[1] + mc.z * c.z + mc.x * c.x;
    i[2] = i[2] + ic[2] + mc.x * c.x + mc.y * c.y, i[3] = i[3] + ic[3] - mc.x * c.y;
    i[4] = i[4] + ic[4] - mc.y * c.z, i[5] = i[5] + ic[5] - mc.z * c.x;
  }
  // o's inertia, turned by E and moved by t
  template <class Turn>
  KANE_ALWAYS_INLINE void add(const composite_inertia& o, const Turn& e, const v3<S>& t) {
    const v3<S> h1 = e.up(o.h), mt = o.mass * t;
    const sym3<S> i1 = e.up(o.i);
    const S d = S(2) * dot3(t, h1) + dot3(mt, t);
    mass = mass + o.mass, h = h + h1 + mt;
    i[0] = i[0] + i1[0] + d - S(2) * t.x * h1.x - mt.x * t.x;
    i[1] = i[1] + i1[1] + d - S(2) * t.y * h1.y - mt.y * t.y;
    i[2] = i[2] + i1[2] + d - S(2) * t.z * h1.z - mt.z * t.z;
    i[3] = i[3] + i1[3] - t.x * h1.y - h1.x * t.y - mt.x * t.y;
    i[4] = i[4] + i1[4] - t.y * h1.z - h1.y * t.z - mt.y * t.z;
    i[5] = i[5] + i1[5] - t.z * h1.x - h1.z * t.x - mt.z * t.x;
  }
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

// The force (n about o_F, f) in F's components carried to the frames above F: M_rs = k_r . n there.
template <class JF, std::size_t F, class BF, class S, class Out>
KANE_ALWAYS_INLINE void column_up(const BF& bf, v3<S> n, v3<S> f, Out& M, Eigen::Index s) {
  constexpr auto& t = JF::table;
  constexpr int p = t.parent[F];
  if constexpr (p > 0) {
    const auto& e = std::get<F>(bf.e);
    f = e.up(f);
    n = e.up(n) + cross3(bf.offset[F], f);
    constexpr int r = t.speed[std::size_t(p)];
    if constexpr (r >= 0) {
      const S x =
          dot3(joint_axis_in_frame<typename at<typename JF::frame_list, std::size_t(p)>::type, S>(), n);
      M(Eigen::Index(r), s) = x, M(s, Eigen::Index(r)) = x;
    }
    column_up<JF, std::size_t(p)>(bf, n, f, M, s);
  }
}

// M of the joint-form system Sys.
template <class JF, class Sys, class Ev, class Out>
KANE_ALWAYS_INLINE void composite_mass_matrix(const body_frames<JF, Ev>& bf, const Ev& ev, Out& M) {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  constexpr auto& t = JF::table;
  constexpr std::size_t nf = JF::nf;
  std::array<composite_inertia<S>, nf> c;
  for (auto& x : c) x.mass = S(0), x.h = {S(0), S(0), S(0)}, x.i = {S(0), S(0), S(0), S(0), S(0), S(0)};
  [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
    (
        [&] {
          constexpr int f = t.item_frame[I];
          if constexpr ((is_particle<X> || is_body<X>)&&f > 0) {
            const vec at = bf.template local<t.item_point[I], f>();
            if constexpr (is_body<X>)
              c[std::size_t(f)].add_mass(S(eval_scalar(X::mass, ev)), at, body_inertia<X>(ev));
            else
              c[std::size_t(f)].add_mass(S(eval_scalar(X::mass, ev)), at,
                                         {S(0), S(0), S(0), S(0), S(0), S(0)});
          }
        }(),
        ...);
  }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  static_for<nf - 1>([&](auto j) {  // leaves first
    constexpr std::size_t f = nf - 1 - j;
    if constexpr (t.parent[f] > 0) c[std::size_t(t.parent[f])].add(c[f], std::get<f>(bf.e), bf.offset[f]);
  });
  M.setZero();
  static_for<JF::n>([&](auto s) {
    constexpr std::size_t f = std::size_t(t.joint_frame[s]);
    const vec k = joint_axis_in_frame<typename at<typename JF::frame_list, f>::type, S>();
    const composite_inertia<S>& x = c[f];
    M(Eigen::Index(s), Eigen::Index(s)) = dot3(k, sym_times(x.i, k));
    column_up<JF, f>(bf, sym_times(x.i, k), cross3(k, x.h), M, Eigen::Index(s));
  });
}

}  // namespace kane::detail
