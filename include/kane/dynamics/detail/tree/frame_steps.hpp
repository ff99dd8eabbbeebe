// Loops over the frames of a system of joint form at run time (aba.hpp, rnea_derivatives.hpp):
// each frame's step is one of a few variants, by its turn's axis (x, y, z, or 3 for a general E)
// and its offset's (none, along x, y or z, or general), compiled once each and chosen per frame.
// A variant's number is 5 axis + offset; a model compiles the variants it uses. And what each
// frame's own items give the loops: their inertia and their loads.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"
#include "kane/dynamics/detail/tree/turns.hpp"
#include "kane/kinematics/derivative.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class BF>
constexpr int variant_of(std::size_t g) {
  const int a = BF::axes[g] < 0 ? 3 : BF::axes[g];
  const auto o = BF::offset_pattern(g);
  const bool x = o[0] != entry::zero, y = o[1] != entry::zero, z = o[2] != entry::zero;
  return 5 * a + (!x && !y && !z ? 0 : x && !y && !z ? 1 : !x && y && !z ? 2 : !x && !y && z ? 3 : 4);
}
template <int V>
constexpr std::array<entry, 3> variant_offset() {
  constexpr int o = V % 5;
  constexpr entry x = o == 1 || o == 4 ? entry::other : entry::zero,
                  y = o == 2 || o == 4 ? entry::other : entry::zero,
                  z = o == 3 || o == 4 ? entry::other : entry::zero;
  return {x, y, z};
}
template <int V>
constexpr std::array<entry, 3> variant_axis() {
  constexpr int a = V / 5;
  if constexpr (a == 3)
    return {entry::other, entry::other, entry::other};
  else
    return {a == 0 ? entry::one : entry::zero, a == 1 ? entry::one : entry::zero,
            a == 2 ? entry::one : entry::zero};
}
template <class BF, std::size_t NF>
struct variants {
  std::array<int, 20> used{};
  std::size_t n = 0;
  constexpr variants() {
    for (std::size_t g = 1; g < NF; ++g) {
      const int v = variant_of<BF>(g);
      bool seen = false;
      for (std::size_t k = 0; k < n; ++k) seen = seen || used[k] == v;
      if (!seen) used[n++] = v;
    }
  }
};
// f(std::integral_constant<int, V>) for the variant V of a frame
template <auto Used, class F, std::size_t... I>
KANE_ALWAYS_INLINE void with_variant(int v, F&& f, std::index_sequence<I...>) {
  (void)((v == Used.used[I] ? (f(std::integral_constant<int, Used.used[I]>{}), true) : false) || ...);
}

// Each frame's turn at run time: cos and sin about its coordinate axis, or its E and joint axis.
// at(g, f) calls f(E, K, O, k): the turn, the patterns of its joint axis and offset, the axis.
template <class JF, class Ev>
struct frame_steps {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  using BF = body_frames<JF, Ev>;
  static constexpr std::size_t nf = JF::nf;
  static constexpr variants<BF, nf> used{};
  static constexpr std::array<int, nf> variant = [] {
    std::array<int, nf> out{};
    for (std::size_t g = 1; g < nf; ++g) out[g] = variant_of<BF>(g);
    return out;
  }();
  std::array<S, nf> c, s;               // cos, sin of each frame's turn about a coordinate axis
  std::array<turn<S, -1>, nf> general;  // or its E
  std::array<vec, nf> k;                // and its joint's axis

  KANE_ALWAYS_INLINE explicit frame_steps(const BF& bf) {
    static_for<nf - 1>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
      constexpr std::size_t g = i + 1;
      const auto& e = std::get<g>(bf.e);
      if constexpr (BF::axes[g] >= 0)
        c[g] = e.c, s[g] = e.s;
      else
        general[g] = e, k[g] = joint_axis_in_frame<frame_at<JF, g>, S>();
    });
  }
  template <class F>
  KANE_ALWAYS_INLINE void at(std::size_t g, F&& f) const {
    with_variant<used>(
        variant[g],
        [&](auto v) KANE_ALWAYS_INLINE_LAMBDA {
          constexpr int a = decltype(v)::value / 5;
          using K = std::integral_constant<std::array<entry, 3>, variant_axis<decltype(v)::value>()>;
          using O = std::integral_constant<std::array<entry, 3>, variant_offset<decltype(v)::value>()>;
          if constexpr (a < 3)
            f(turn<S, a>{c[g], s[g]}, K{}, O{}, vec{S(a == 0), S(a == 1), S(a == 2)});
          else
            f(general[g], K{}, O{}, k[g]);
        },
        std::make_index_sequence<used.n>{});
  }
};

// Each frame's own items' inertia about its origin: the table of numbers where literals give it.
template <class JF, class Sys, class Ev>
KANE_ALWAYS_INLINE void own_inertias(const body_frames<JF, Ev>& bf, const Ev& ev,
                                     std::array<composite_inertia<typename Ev::scalar>, JF::nf>& out) {
  using S = typename Ev::scalar;
  using BF = body_frames<JF, Ev>;
  using known = known_inertias<JF, Sys, BF>;
  static constexpr auto& t = JF::table;
  if constexpr (known::value)
    for (std::size_t g = 0; g < JF::nf; ++g) {
      const composite_inertia<double>& o = known::own[g];
      out[g] = {S(o.mass),
                {S(o.h.x), S(o.h.y), S(o.h.z)},
                {S(o.i[0]), S(o.i[1]), S(o.i[2]), S(o.i[3]), S(o.i[4]), S(o.i[5])}};
    }
  else {
    out.fill({S(0), {S(0), S(0), S(0)}, {S(0), S(0), S(0), S(0), S(0), S(0)}});
    [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
      (
          [&] {
            constexpr int g = t.item_frame[I];
            if constexpr ((is_body<X> || is_particle<X>)&&g > 0) {
              constexpr int ip = t.item_point[I];
              add_item_mass<X, BF::local_pattern(ip, g)>(out[std::size_t(g)], bf.template local<ip, g>(), ev);
            }
          }(),
          ...);
    }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
  }
}

// Some frame below the root has applied loads (own_loads)
template <class JF, class Sys>
inline constexpr bool loads_below_root =
    []<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
      return ((!is_gravity<X> && !is_body<X> && !is_particle<X> && JF::table.item_frame[I] > 0) || ...);
    }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});

// The vector of the load X, or its partial derivative by the leaf By (an input r_i).
template <class X, class By, class R>
constexpr auto load_vector() {
  if constexpr (std::is_void_v<By>)
    return X::vector;
  else
    return partial_in<R, By>(X::vector);
}

// Each frame's applied loads negated, -f_ext: the force f and its moment n about the frame's origin,
// in its components; with By, their partial derivatives by By.
template <class JF, class Sys, class By = void, class Ev>
KANE_ALWAYS_INLINE void own_loads(const body_frames<JF, Ev>& bf, const Ev& ev,
                                  std::array<v3<typename Ev::scalar>, JF::nf>& f,
                                  std::array<v3<typename Ev::scalar>, JF::nf>& n) {
  using S = typename Ev::scalar;
  using BF = body_frames<JF, Ev>;
  static constexpr auto& t = JF::table;
  f.fill({S(0), S(0), S(0)}), n.fill({S(0), S(0), S(0)});
  [&]<class... X, std::size_t... I>(list<X...>, std::index_sequence<I...>) {
    (
        [&] {
          constexpr int g = t.item_frame[I];
          if constexpr (!is_gravity<X> && !is_body<X> && !is_particle<X> && g > 0) {
            constexpr int ip = t.item_point[I];
            subtract_load<X, frame_at<JF, std::size_t(g)>, BF::local_pattern(ip, g),
                          load_vector<X, By, frame_at<JF, 0>>()>(f[std::size_t(g)], n[std::size_t(g)],
                                                                 bf.template local<ip, g>(), ev);
          }
        }(),
        ...);
  }(typename Sys::items{}, std::make_index_sequence<size<typename Sys::items>::value>{});
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
