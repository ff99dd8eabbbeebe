// When Kane's sums regroup over the tree (crba.hpp, rnea.hpp): the joint form
// of a system, decided at compile time.
//
// Every speed u_r = q_c' turns exactly one edge of the frame tree, a simple rotation by q_c
// about an axis k_r (other edges turn by constant angles), but for at most one free joint below
// the root (speed_layout.hpp); every point of the system is a chain of vectors, each fixed in a
// frame, from the root's origin, down one path of the tree (the free joint's origin moves along
// the root's axes). Then for every item below the edge of u_r, w_r = k_r and
// v_r(P) = k_r x (P - X_r) = k_r x P + X_r x k_r, X_r the point of the chain where its vectors
// below the edge begin; when all items below the edge share X_r, u_r's partial velocities are
// one screw S_r = (k_r, X_r x k_r) and the composite-body sums hold. The tables are constexpr
// arrays of indices: their cost grows like the model, not its square.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/tree/fixed_vectors.hpp"
#include "kane/dynamics/detail/tree/joint_table.hpp"
#include "kane/dynamics/detail/tree/speed_layout.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/kinematics/point.hpp"
#include "kane/speeds/kinematic_weights.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The frame a vector is fixed in, void for none.
template <class F>
struct frame_or_void {
  using type = std::conditional_t<std::is_same_v<F, no_frame>, void, F>;
};
// The frame the vector from P's predecessor to P is fixed in (no_frame for an origin), or the
// frame along whose axes a free joint's coordinates move P (speed_layout.hpp).
template <class P>
struct segment_frame {
  using V = std::remove_cv_t<decltype(P::position)>;
  using type = std::conditional_t<translation<V>::coordinate != 0, typename translation<V>::frame,
                                  typename fixed_frame_of<V>::type>;
};
template <class F>
struct segment_frame<origin<F>> {
  using type = no_frame;
};

template <class T, class... Ts>
constexpr int index_in(list<Ts...>) {
  int i = 0, found = -1;
  ((std::is_same_v<T, Ts> ? void(found = i) : void(), ++i), ...);
  return found;
}

// The point of an item (its mass centre, its particle, the point of a force), or void.
template <class X>
struct item_point {
  using type = void;
};
template <class X>
requires(is_particle<X> || is_force<X>) struct item_point<X> {
  using type = typename X::point;
};
template <class X>
requires is_body<X>
struct item_point<X> {
  using type = typename X::centre;
};
// The frame of a body or a torque, or void.
template <class X>
struct item_frame {
  using type = void;
};
template <class X>
requires(is_body<X> || is_torque<X>) struct item_frame<X> {
  using type = typename X::frame;
};

template <class P>
struct point_up {
  using type = typename P::from;
};
template <class... P>
struct point_closure : tree_union<point_up, list<>, P...> {};
template <class... F>
struct frame_closure : tree_union<frame_up, list<>, F...> {};

// The kind of the edge above F: 1 + r for a simple rotation by q_r, 0 for a constant edge, -1 else.
template <class F>
constexpr int edge_kind() {
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return 0;
  else if constexpr (spin_edge<F> || matrix_edge<F>)
    return -1;
  else if constexpr (F::step::coordinate_index != 0)
    return int(F::step::coordinate_index);
  else
    return constant_edge<F>() ? 0 : -1;
}

// Facts of the frames, points and items: arrays filled by pack expansions.
template <class P, class Points>
constexpr int from_index() {
  if constexpr (requires { typename P::fixed_frame; })
    return -1;
  else
    return index_in<typename P::from>(Points{});
}
template <class P>
constexpr std::size_t translated() {
  if constexpr (requires { typename P::fixed_frame; })
    return 0;
  else
    return translation<std::remove_cv_t<decltype(P::position)>>::coordinate;
}
template <class P, class R>
constexpr bool origin_of() {  // an origin fixed in R, or no origin
  if constexpr (requires { typename P::fixed_frame; })
    return std::is_same_v<typename P::fixed_frame, R>;
  else
    return true;
}
template <class T, class L>
constexpr int index_or_none() {
  if constexpr (std::is_void_v<T> || std::is_same_v<T, no_frame> || std::is_same_v<T, mixed_frame>)
    return -1;
  else
    return index_in<T>(L{});
}
template <class FL>
struct frame_facts;
template <class... F>
struct frame_facts<list<F...>> {
  static constexpr std::array<int, sizeof...(F)> parent{
      index_or_none<typename F::tree_parent, list<F...>>()...};
  static constexpr std::array<int, sizeof...(F)> kind{edge_kind<F>()...};
};
template <class PL, class FL, class R>
struct point_facts;
template <class... P, class FL, class R>
struct point_facts<list<P...>, FL, R> {
  static constexpr std::array<int, sizeof...(P)> from{from_index<P, list<P...>>()...};
  static constexpr std::array<bool, sizeof...(P)> origin{origin_of<P, R>()...};
  static constexpr std::array<std::size_t, sizeof...(P)> moved{translated<P>()...};
  static constexpr std::array<int, sizeof...(P)> segment{
      index_or_none<typename segment_frame<P>::type, FL>()...};
};
template <class XL, class PL, class FL>
struct item_facts;
template <class... X, class PL, class FL>
struct item_facts<list<X...>, PL, FL> {
  static constexpr std::array<int, sizeof...(X)> point{index_or_none<typename item_point<X>::type, PL>()...};
  static constexpr std::array<int, sizeof...(X)> frame{index_or_none<typename item_frame<X>::type, FL>()...};
};
template <class... G>
constexpr bool none_mixed(list<G...>) {
  return (!std::is_same_v<G, mixed_frame> && ...);
}

template <class Sys, class R, class Sp>
struct joint_form {
  using items = typename Sys::items;
  using points = typename not_void<typename map_items<item_point, items>::type>::type;
  using all_points = typename apply_list<point_closure, points>::type;
  using segment_frames = typename map_items<segment_frame, all_points>::type;
  static constexpr bool fixed_segments = none_mixed(segment_frames{});
  using item_frames = typename not_void<typename map_items<item_frame, items>::type>::type;
  using frame_list = typename apply_list<
      frame_closure,
      std::conditional_t<fixed_segments,
                         typename concat<list<R>, item_frames,
                                         typename not_void<typename map_items<
                                             frame_or_void, segment_frames>::type>::type>::type,
                         list<R>>>::type;
  static constexpr std::size_t nf = size<frame_list>::value, np = size<all_points>::value,
                               ni = size<items>::value, n = Sp::n;

  static constexpr auto table = [] {
    joint_table<nf, np, ni, n> t;
    constexpr std::size_t nq = Sp::rows;
    constexpr auto layout = layout_of<Sp, R, frame_list, nq>::value;
    if constexpr (!fixed_segments || !layout.holds)
      return t;
    else {
      using frames = frame_facts<frame_list>;
      using pts = point_facts<all_points, frame_list, R>;
      using its = item_facts<items, all_points, frame_list>;
      bool ok = true;
      std::array<int, n> edges{};
      t.free = layout.free;
      int free_point = -1;  // the free joint's origin
      for (std::size_t i = 0; i < nf; ++i) {
        const int kind = frames::kind[i];
        t.parent[i] = frames::parent[i];
        t.depth[i] = i == 0 ? 0 : t.depth[std::size_t(t.parent[i])] + 1;
        const int r = kind > 0 && kind <= int(nq) ? layout.rate[std::size_t(kind - 1)] : -1;
        t.speed[i] = r;
        ok = ok && (i == 0) == (t.parent[i] < 0);
        if (int(i) == t.free)
          for (std::size_t k = 0; k < 6; ++k) ++edges[k], t.joint_frame[k] = int(i);
        else
          ok = ok && kind >= 0 && (kind == 0 || r >= 0);
        if (r >= 0) ++edges[std::size_t(r)], t.joint_frame[std::size_t(r)] = int(i);
      }
      for (int e : edges) ok = ok && e == 1;
      for (std::size_t i = 0; i < np; ++i) {  // one origin, fixed in R; the free joint's origin
        t.from[i] = pts::from[i], t.segment[i] = pts::segment[i];
        ok = ok && pts::origin[i] && (t.from[i] >= 0 || i == 0);
        if (pts::moved[i] != 0) {
          ok = ok && t.free >= 0 && free_point < 0 && pts::moved[i] == layout.position && t.from[i] == 0 &&
               t.segment[i] == 0;
          free_point = int(i);
        }
      }
      if (!ok) return t;
      // the frames of each chain down one path: attach is the deepest
      for (std::size_t p = 0; p < np; ++p) {
        const int f = t.from[p] < 0 ? 0 : t.attach[std::size_t(t.from[p])], g = t.segment[p];
        ok = ok && (g < 0 || t.below(g, f));
        t.attach[p] = int(p) == free_point ? t.free : g < 0 ? f : g;
      }
      for (std::size_t i = 0; i < ni; ++i) {
        const int p = its::point[i], f = its::frame[i];
        t.item_frame[i] = f >= 0 ? f : p >= 0 ? t.attach[std::size_t(p)] : -1;
        t.item_point[i] = p;
        if (f >= 0 && p >= 0) ok = ok && t.below(f, t.attach[std::size_t(p)]);  // a body's centre
      }
      // one joint point X_r for every item below the edge of u_r, g its frame: the point where the
      // chain of the item's point p first has a vector fixed at or below g (p if none). The chain of p
      // is walked once, for the frames g from the item's up.
      std::array<int, n> x{};
      x.fill(-1);
      for (std::size_t i = 0; i < ni && ok; ++i) {
        const int p = t.item_point[i], f = t.item_frame[i];
        int c = p, y = p;
        for (int g = p < 0 ? -1 : f; g >= 0; g = t.parent[std::size_t(g)]) {
          for (; c >= 0 && t.from[std::size_t(c)] >= 0; c = t.from[std::size_t(c)]) {
            const int s = t.segment[std::size_t(c)];
            if (s >= 0 && t.depth[std::size_t(s)] < t.depth[std::size_t(g)]) break;
            if (s >= 0) y = t.from[std::size_t(c)];
          }
          const int r0 = g == t.free ? 0 : t.speed[std::size_t(g)], r1 = g == t.free ? 6 : r0 + 1;
          for (int r = r0; r >= 0 && r < r1; ++r) {
            ok = ok && (x[std::size_t(r)] < 0 || x[std::size_t(r)] == y);
            x[std::size_t(r)] = y;
          }
        }
      }
      for (std::size_t r = 0; r < n && ok; ++r) {
        const int g = t.joint_frame[r];
        t.joint_point[r] = x[r];
        int a = t.parent[std::size_t(g)];
        while (a >= 0 && t.speed[std::size_t(a)] < 0 && a != t.free) a = t.parent[std::size_t(a)];
        t.parent_speed[r] = g == t.free ? int(r) - 1 : a < 0 ? -1 : a == t.free ? 5 : t.speed[std::size_t(a)];
      }
      if (t.free >= 0) ok = ok && free_point >= 0 && t.joint_point[0] == free_point;
      t.holds = ok;
      if (ok) t.local = local_origins(t);
      return t;
    }
  }();
  static constexpr bool holds = table.holds;
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
