// Spatial inertias in body coordinates (crba.hpp, rnea.hpp, aba.hpp): a composite of
// items about a frame's origin, (m, h = sum m c, I_o = sum I_C + m (|c|^2 1 - c c)), and
// moved to the parent (turned by E, shifted by t); for models given by literals, each
// frame's own items' inertia and the patterns of the composites' first moments at compile time.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/choices.hpp"
#include "kane/detail/inline.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/tree/body_frames.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S>
struct composite_inertia {
  S mass;
  v3<S> h;
  sym3<S> i;  // about the frame's origin

  // m at c (of pattern C) with the inertia ic about c (none: a particle)
  template <std::array<entry, 3> C, item_kind Kind>
  KANE_ALWAYS_INLINE void add_mass(const S& m, const v3<S>& c, const sym3<S>& ic) {
    constexpr auto mp = scaled_pattern(C);
    const v3<S> mc{product<entry::other, C[0]>(m, c.x), product<entry::other, C[1]>(m, c.y),
                   product<entry::other, C[2]>(m, c.z)};
    mass = mass + m;
    h = {plus_product<entry::one, mp[0]>(h.x, S(1), mc.x), plus_product<entry::one, mp[1]>(h.y, S(1), mc.y),
         plus_product<entry::one, mp[2]>(h.z, S(1), mc.z)};
    sym3<S> j = i;
    if constexpr (Kind == item_kind::body)
      static_for<6>([&](auto k) KANE_ALWAYS_INLINE_LAMBDA {
        j[k] = j[k] + ic[k];
      });  // unrolled: no loop through memory
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
    static_for<6>([&](auto k) KANE_ALWAYS_INLINE_LAMBDA { i[k] = i[k] + i1[k]; });  // unrolled, as above
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
    static_for<6>([&](auto k)
                      KANE_ALWAYS_INLINE_LAMBDA { o[k] = S(eval_scalar(std::get<k>(I::components), ev)); });
  } else {  // fixed in the body, or the same in both (a wheel): A^T (I in the root) A
    const Eigen::Matrix<S, 3, 3> a = ev.template axes<typename X::frame>();
    const Eigen::Matrix<S, 3, 3> r = a.transpose() * inertia_in_root<I>(ev) * a;
    o = {r(0, 0), r(1, 1), r(2, 2), r(0, 1), r(1, 2), r(2, 0)};
  }
  return o;
}

// The mass of item X (a particle or a body) at c, of pattern C, added to the composite inertia k.
template <class X, auto C, class S, class Ev>
KANE_ALWAYS_INLINE void add_item_mass(composite_inertia<S>& k, const v3<S>& c, const Ev& ev) {
  if constexpr (is_body<X>)
    k.template add_mass<C, item_kind::body>(S(eval_scalar(X::mass, ev)), c, body_inertia<X>(ev));
  else
    k.template add_mass<C, item_kind::particle>(S(eval_scalar(X::mass, ev)), c, {});
}

template <class JF, std::size_t F>
using frame_at = typename at<typename JF::frame_list, F>::type;

}  // namespace kane::detail
#pragma GCC diagnostic pop
