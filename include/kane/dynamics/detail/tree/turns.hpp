// The turn of an edge of a system of joint form, E_F (v_P = E_F v_F): for a simple
// rotation by q about a coordinate axis a, the 2 x 2 block of the other two axes by
// cos q and sin q from the evaluator's cache (a symmetric matrix's block by cos 2q and
// sin 2q); else E_F = (^R P^P)(^R P^F)^T from the evaluator's pass.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/detail/v3.hpp"
#include "kane/frames/axis.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S>
KANE_ALWAYS_INLINE v3<S> sym_times(const sym3<S>& i, const v3<S>& k) {
  return {i[0] * k.x + i[3] * k.y + i[5] * k.z, i[3] * k.x + i[1] * k.y + i[4] * k.z,
          i[5] * k.x + i[4] * k.y + i[2] * k.z};
}

// E about the coordinate axis A (0, 1, 2): the axes B = A + 1, C = A + 2 turn.
template <class S, int A>
struct turn {
  S c, s;
  static constexpr int axis = A, b = (A + 1) % 3, d = (A + 2) % 3;
  KANE_ALWAYS_INLINE m3<S> after(const m3<S>& r) const {  // R E by columns, R by columns
    m3<S> o = r;
    o[std::size_t(b)] = c * r[std::size_t(b)] + s * r[std::size_t(d)];
    o[std::size_t(d)] = c * r[std::size_t(d)] - s * r[std::size_t(b)];
    return o;
  }
  KANE_ALWAYS_INLINE v3<S> up(v3<S> v) const {  // E v
    const S x = comp<std::size_t(b)>(v), y = comp<std::size_t(d)>(v);
    comp<std::size_t(b)>(v) = c * x - s * y, comp<std::size_t(d)>(v) = s * x + c * y;
    return v;
  }
  KANE_ALWAYS_INLINE v3<S> down(v3<S> v) const {  // E^T v
    const S x = comp<std::size_t(b)>(v), y = comp<std::size_t(d)>(v);
    comp<std::size_t(b)>(v) = c * x + s * y, comp<std::size_t(d)>(v) = c * y - s * x;
    return v;
  }
  template <std::array<entry, 3> P>  // E^T v, v of pattern P
  KANE_ALWAYS_INLINE v3<S> down_along(const v3<S>& v) const {
    if constexpr (P[b] == entry::zero && P[d] == entry::zero)
      return v;
    else
      return down(v);
  }
  template <std::array<entry, 3> P>  // E v
  KANE_ALWAYS_INLINE v3<S> up_along(const v3<S>& v) const {
    if constexpr (P[b] == entry::zero && P[d] == entry::zero)
      return v;
    else
      return up(v);
  }
  // The pattern of E v
  static constexpr std::array<entry, 3> turned(std::array<entry, 3> p) {
    if (p[b] != entry::zero || p[d] != entry::zero) p[b] = p[d] = entry::other;
    if (p[A] != entry::zero) p[A] = entry::other;
    return p;
  }
  KANE_ALWAYS_INLINE sym3<S> up(const sym3<S>& i) const {  // E I E^T, through cos 2q and sin 2q
    constexpr std::size_t bb = sym_index[b][b], dd = sym_index[d][d], bd = sym_index[b][d],
                          ab = sym_index[A][b], ad = sym_index[A][d];
    const S c2 = c * c - s * s, s2 = S(2) * c * s, mean = S(0.5) * (i[bb] + i[dd]),
            diff = S(0.5) * (i[bb] - i[dd]);
    sym3<S> o = i;
    o[bb] = mean + diff * c2 - i[bd] * s2, o[dd] = mean - diff * c2 + i[bd] * s2,
    o[bd] = diff * s2 + i[bd] * c2;
    o[ab] = c * i[ab] - s * i[ad], o[ad] = s * i[ab] + c * i[ad];
    return o;
  }
  KANE_ALWAYS_INLINE m3<S> up(const m3<S>& m) const {  // E M E^T: rows b and d mixed, then each row
    m3<S> o = m;
    o[std::size_t(b)] = c * m[std::size_t(b)] - s * m[std::size_t(d)];
    o[std::size_t(d)] = s * m[std::size_t(b)] + c * m[std::size_t(d)];
    return {up(o[0]), up(o[1]), up(o[2])};
  }
};
// Any other edge: E from the evaluator's axes.
template <class S>
struct turn<S, -1> {
  Eigen::Matrix<S, 3, 3> e;
  static constexpr int axis = -1;
  KANE_ALWAYS_INLINE m3<S> after(const m3<S>& r) const {  // R E by columns, R by columns
    m3<S> o;
    for (std::size_t j = 0; j < 3; ++j) {
      const auto k = Eigen::Index(j);
      o[j] = e(0, k) * r[0] + e(1, k) * r[1] + e(2, k) * r[2];
    }
    return o;
  }
  KANE_ALWAYS_INLINE v3<S> up(const v3<S>& v) const {
    return {e(0, 0) * v.x + e(0, 1) * v.y + e(0, 2) * v.z, e(1, 0) * v.x + e(1, 1) * v.y + e(1, 2) * v.z,
            e(2, 0) * v.x + e(2, 1) * v.y + e(2, 2) * v.z};
  }
  KANE_ALWAYS_INLINE v3<S> down(const v3<S>& v) const {
    return {e(0, 0) * v.x + e(1, 0) * v.y + e(2, 0) * v.z, e(0, 1) * v.x + e(1, 1) * v.y + e(2, 1) * v.z,
            e(0, 2) * v.x + e(1, 2) * v.y + e(2, 2) * v.z};
  }
  template <std::array<entry, 3> P>
  KANE_ALWAYS_INLINE v3<S> down_along(const v3<S>& v) const {
    return down(v);
  }
  template <std::array<entry, 3> P>
  KANE_ALWAYS_INLINE v3<S> up_along(const v3<S>& v) const {
    return up(v);
  }
  static constexpr std::array<entry, 3> turned(const std::array<entry, 3>& p) {
    return all_zero(p) ? p : std::array<entry, 3>{entry::other, entry::other, entry::other};
  }
  KANE_ALWAYS_INLINE m3<S> up(const m3<S>& m) const {  // E M E^T
    const m3<S> r{e(0, 0) * m[0] + e(0, 1) * m[1] + e(0, 2) * m[2],
                  e(1, 0) * m[0] + e(1, 1) * m[1] + e(1, 2) * m[2],
                  e(2, 0) * m[0] + e(2, 1) * m[1] + e(2, 2) * m[2]};
    return {up(r[0]), up(r[1]), up(r[2])};
  }
  KANE_ALWAYS_INLINE sym3<S> up(const sym3<S>& i) const {
    sym3<S> o;
    static_for<6>([&](auto k) {
      constexpr std::size_t r = k < 3    ? k
                                : k == 3 ? 0
                                : k == 4 ? 1
                                         : 2,
                            q = k < 3    ? k
                                : k == 3 ? 1
                                : k == 4 ? 2
                                         : 0;
      S x = S(0);
      static_for<9>([&](auto jl) {
        constexpr std::size_t j = jl / 3, l = jl % 3;
        x = x +
            e(Eigen::Index(r), Eigen::Index(j)) * i[sym_index[j][l]] * e(Eigen::Index(q), Eigen::Index(l));
      });
      o[k] = x;
    });
    return o;
  }
};

template <class F>
constexpr int turn_axis() {
  if constexpr (requires { F::step::coordinate_index; } && !spin_edge<F> && !matrix_edge<F>) {
    if constexpr (F::step::coordinate_index != 0) return unit_axis<typename F::step::axis>::principal;
  }
  return -1;
}
template <class F, class Ev>
KANE_ALWAYS_INLINE turn<typename Ev::scalar, turn_axis<F>()> make_turn(const Ev& ev) {
  constexpr int a = turn_axis<F>();
  if constexpr (a >= 0) {
    constexpr std::size_t i = F::step::coordinate_index;
    return {ev.template cos_q<i>(), ev.template sin_q<i>()};
  } else if constexpr (std::is_void_v<typename F::tree_parent::tree_parent>)
    return {ev.template axes<F>()};
  else
    return {ev.template axes<typename F::tree_parent>().transpose() * ev.template axes<F>()};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
