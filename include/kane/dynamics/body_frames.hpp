// Body coordinates of a system of joint form (joint_form.hpp), for the recursive
// sums (crba.hpp, rnea.hpp): every frame F of the tree has an origin o_F, the
// point of its joint axis; its edge turns it from its parent P by E_F
// (v_P = E_F v_F; for a simple rotation by q about a coordinate axis a, the
// 2 x 2 block of the other two axes: cos q and sin q from the evaluator's cache,
// else E_F = (^R P^P)(^R P^F)^T from its pass), and o_F = o_P + t_F with t_F in
// P's components. Points are located from the origin of the frame of their last
// vector, in that frame's components: the numbers of a model given by literals
// are constants the compiler folds.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/patterned.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/joint_form.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/frames/axis.hpp"

namespace kane::detail {

// A symmetric 3 x 3 matrix: 11 22 33 12 23 31.
template <class S>
using sym3 = std::array<S, 6>;
inline constexpr std::size_t sym_at[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
template <class S>
KANE_ALWAYS_INLINE v3<S> sym_times(const sym3<S>& i, const v3<S>& k) {
  return {i[0] * k.x + i[3] * k.y + i[5] * k.z, i[3] * k.x + i[1] * k.y + i[4] * k.z,
          i[5] * k.x + i[4] * k.y + i[2] * k.z};
}
template <int I, class S>
KANE_ALWAYS_INLINE S& component_ref(v3<S>& v) {
  return I == 0 ? v.x : I == 1 ? v.y : v.z;
}

// E about the coordinate axis A (0, 1, 2): the axes B = A + 1, C = A + 2 turn.
template <class S, int A>
struct turn {
  S c, s;
  static constexpr int b = (A + 1) % 3, d = (A + 2) % 3;
  KANE_ALWAYS_INLINE v3<S> up(v3<S> v) const {  // E v
    const S x = component_ref<b>(v), y = component_ref<d>(v);
    component_ref<b>(v) = c * x - s * y, component_ref<d>(v) = s * x + c * y;
    return v;
  }
  KANE_ALWAYS_INLINE v3<S> down(v3<S> v) const {  // E^T v
    const S x = component_ref<b>(v), y = component_ref<d>(v);
    component_ref<b>(v) = c * x + s * y, component_ref<d>(v) = c * y - s * x;
    return v;
  }
  template <std::array<entry, 3> P>  // E^T v, v of pattern P
  KANE_ALWAYS_INLINE v3<S> down_along(const v3<S>& v) const {
    if constexpr (P[b] == entry::zero && P[d] == entry::zero)
      return v;
    else
      return down(v);
  }
  KANE_ALWAYS_INLINE sym3<S> up(const sym3<S>& i) const {  // E I E^T, through cos 2q and sin 2q
    constexpr std::size_t bb = sym_at[b][b], dd = sym_at[d][d], bd = sym_at[b][d], ab = sym_at[A][b],
                          ad = sym_at[A][d];
    const S c2 = c * c - s * s, s2 = S(2) * c * s, mean = S(0.5) * (i[bb] + i[dd]),
            diff = S(0.5) * (i[bb] - i[dd]);
    sym3<S> o = i;
    o[bb] = mean + diff * c2 - i[bd] * s2, o[dd] = mean - diff * c2 + i[bd] * s2,
    o[bd] = diff * s2 + i[bd] * c2;
    o[ab] = c * i[ab] - s * i[ad], o[ad] = s * i[ab] + c * i[ad];
    return o;
  }
};
// Any other edge: E from the evaluator's axes.
template <class S>
struct turn<S, -1> {
  Eigen::Matrix<S, 3, 3> e;
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
        x = x + e(Eigen::Index(r), Eigen::Index(j)) * i[sym_at[j][l]] * e(Eigen::Index(q), Eigen::Index(l));
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

// The components of a vector fixed in its frame (fixed_frame_of), in that frame.
template <class V, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> own_components(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (is_zero_vector_v<V>)
    return {S(0), S(0), S(0)};
  else if constexpr (is_unit<V>::value)
    return {S(V::index == 1), S(V::index == 2), S(V::index == 3)};
  else if constexpr (is_v<V, scaled>)
    return S(eval_scalar(v.s, ev)) * own_components(v.v, ev);
  else if constexpr (is_v<V, vsum>)
    return own_components(v.l, ev) + own_components(v.r, ev);
  else if constexpr (is_v<V, vdiff>)
    return own_components(v.l, ev) - own_components(v.r, ev);
  else
    return -own_components(v.v, ev);
}

// A scalar known at compile time (literals, constants and their arithmetic), and its value.
template <class X>
constexpr bool known_scalar() {
  if constexpr (std::is_same_v<X, literal> || is_constant<X>::value || is_fixed<X>::value)
    return true;
  else if constexpr (is_v<X, add> || is_v<X, sub> || is_v<X, mul> || is_v<X, quot>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().l)>>() &&
           known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().r)>>();
  else if constexpr (is_v<X, neg>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const X&>().x)>>();
  else
    return false;
}
template <class X>
constexpr double known_value(const X& x) {
  if constexpr (std::is_same_v<X, literal>)
    return x.value;
  else if constexpr (is_constant<X>::value)
    return double(X::num) / double(X::den);
  else if constexpr (is_fixed<X>::value)
    return X::value;
  else if constexpr (is_v<X, add>)
    return known_value(x.l) + known_value(x.r);
  else if constexpr (is_v<X, sub>)
    return known_value(x.l) - known_value(x.r);
  else if constexpr (is_v<X, mul>)
    return known_value(x.l) * known_value(x.r);
  else if constexpr (is_v<X, quot>)
    return known_value(x.l) / known_value(x.r);
  else
    return -known_value(x.x);
}
// The same for the components of a vector fixed in its frame (own_components).
template <class V>
constexpr bool known_vector() {
  if constexpr (is_zero_vector_v<V> || is_unit<V>::value)
    return true;
  else if constexpr (is_v<V, scaled>)
    return known_scalar<std::remove_cv_t<decltype(std::declval<const V&>().s)>>() &&
           known_vector<std::remove_cv_t<decltype(std::declval<const V&>().v)>>();
  else if constexpr (is_v<V, vneg>)
    return known_vector<std::remove_cv_t<decltype(std::declval<const V&>().v)>>();
  else
    return known_vector<std::remove_cv_t<decltype(std::declval<const V&>().l)>>() &&
           known_vector<std::remove_cv_t<decltype(std::declval<const V&>().r)>>();
}
template <class V>
constexpr std::array<double, 3> known_components(const V& v) {
  if constexpr (is_zero_vector_v<V>)
    return {0, 0, 0};
  else if constexpr (is_unit<V>::value)
    return {double(V::index == 1), double(V::index == 2), double(V::index == 3)};
  else if constexpr (is_v<V, scaled>) {
    const double k = known_value(v.s);
    const auto a = known_components(v.v);
    return {k * a[0], k * a[1], k * a[2]};
  } else if constexpr (is_v<V, vneg>) {
    const auto a = known_components(v.v);
    return {-a[0], -a[1], -a[2]};
  } else {
    const auto a = known_components(v.l), b = known_components(v.r);
    const double sign = is_v<V, vdiff> ? -1.0 : 1.0;
    return {a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2]};
  }
}

// Which of those components are 0 or 1 at every state.
template <class V>
constexpr std::array<entry, 3> own_pattern() {
  constexpr auto sum = [](std::array<entry, 3> a, std::array<entry, 3> b) {
    for (std::size_t i = 0; i < 3; ++i)
      a[i] = a[i] == entry::zero && b[i] == entry::zero ? entry::zero : entry::other;
    return a;
  };
  if constexpr (is_zero_vector_v<V>)
    return {entry::zero, entry::zero, entry::zero};
  else if constexpr (is_unit<V>::value)
    return {V::index == 1 ? entry::one : entry::zero, V::index == 2 ? entry::one : entry::zero,
            V::index == 3 ? entry::one : entry::zero};
  else if constexpr (is_v<V, scaled> || is_v<V, vneg>)
    return scaled_pattern(own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().v)>>());
  else
    return sum(own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().l)>>(),
               own_pattern<std::remove_cv_t<decltype(std::declval<const V&>().r)>>());
}

// The edge of F as a screw in F: its axis k_F (a unit vector of F), 0 for a constant edge.
template <class F, class S>
KANE_ALWAYS_INLINE v3<S> joint_axis_in_frame() {
  if constexpr (std::is_void_v<typename F::tree_parent> || edge_kind<F>() <= 0)
    return {S(0), S(0), S(0)};
  else {
    constexpr auto k = unit_axis<typename F::step::axis>::value;
    return {S(k[0]), S(k[1]), S(k[2])};
  }
}

// The pattern of the axis of F's edge in F.
template <class F>
constexpr std::array<entry, 3> joint_axis_pattern() {
  if constexpr (std::is_void_v<typename F::tree_parent> || edge_kind<F>() <= 0)
    return {entry::zero, entry::zero, entry::zero};
  else {
    constexpr auto k = unit_axis<typename F::step::axis>::value;
    return {entry_of_number(k[0]), entry_of_number(k[1]), entry_of_number(k[2])};
  }
}

template <class JF, class Ev, class Frames = typename JF::frame_list>
struct body_frames;
template <class JF, class Ev, class... F>
struct body_frames<JF, Ev, list<F...>> {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  static constexpr auto& t = JF::table;
  static constexpr std::size_t nf = JF::nf, np = JF::np;

  static constexpr auto pos_pattern = []<class... P>(list<P...>) {
    std::array<std::array<entry, 3>, np> out{};
    std::size_t i = 0;
    (
        [&] {
          const int from = t.from[i], g = t.segment[i];
          constexpr auto own = own_pattern<std::remove_cv_t<decltype(P::position)>>();
          if (from < 0)
            out[i] = {entry::zero, entry::zero, entry::zero};
          else if (g < 0)
            out[i] = out[std::size_t(from)];
          else if (from == t.origin[std::size_t(g)])
            out[i] = own;
          else
            for (std::size_t j = 0; j < 3; ++j)
              out[i][j] = out[std::size_t(from)][j] == entry::zero && own[j] == entry::zero ? entry::zero
                                                                                            : entry::other;
          ++i;
        }(),
        ...);
    return out;
  }(typename JF::all_points{});
  // Every point's position known at compile time, and the positions.
  static constexpr bool known_positions = [] {
    return []<class... P>(list<P...>) {
      return (known_vector<std::remove_cv_t<decltype(P::position)>>() && ...);
    }(typename JF::all_points{});
  }();
  static constexpr auto known_pos = [] {
    std::array<std::array<double, 3>, np> out{};
    if constexpr (known_positions) {
      std::size_t i = 0;
      [&]<class... P>(list<P...>) {
        (
            [&] {
              const int from = t.from[i], g = t.segment[i];
              const auto own = known_components(P::position);
              if (from < 0)
                out[i] = {0, 0, 0};
              else if (g < 0)
                out[i] = out[std::size_t(from)];
              else if (from == t.origin[std::size_t(g)])
                out[i] = own;
              else
                for (std::size_t j = 0; j < 3; ++j) out[i][j] = out[std::size_t(from)][j] + own[j];
              ++i;
            }(),
            ...);
      }(typename JF::all_points{});
    }
    return out;
  }();
  static constexpr std::array<double, 3> known_local(int p, int f) {
    if (p < 0 || p == t.origin[std::size_t(f)]) return {0, 0, 0};
    return known_pos[std::size_t(p)];
  }

  // The patterns of t_F and of local<P, F>().
  static constexpr std::array<entry, 3> offset_pattern(std::size_t f) {
    const int o = t.origin[f];
    if (f == 0 || o == t.origin[std::size_t(t.parent[f])]) return {entry::zero, entry::zero, entry::zero};
    return pos_pattern[std::size_t(o)];
  }
  static constexpr std::array<entry, 3> local_pattern(int p, int f) {
    if (p < 0 || p == t.origin[std::size_t(f)]) return {entry::zero, entry::zero, entry::zero};
    return pos_pattern[std::size_t(p)];
  }

  std::tuple<turn<S, turn_axis<F>()>...> e;  // e[0], the root's, unused
  std::array<vec, np> pos;                   // P from o of its frame, in its components
  std::array<vec, nf> offset;                // t_F

  KANE_ALWAYS_INLINE explicit body_frames(const Ev& ev)
      : e{[&] {
          if constexpr (std::is_void_v<typename F::tree_parent>)
            return turn<S, -1>{};
          else
            return make_turn<F>(ev);
        }()...} {
    const vec zero{S(0), S(0), S(0)};
    [&]<class... P, std::size_t... I>(list<P...>, std::index_sequence<I...>) {
      (
          [&] {
            constexpr int from = t.from[I], g = t.segment[I];
            if constexpr (from < 0)
              pos[I] = zero;
            else if constexpr (g < 0)
              pos[I] = pos[std::size_t(from)];
            else if constexpr (from == t.origin[std::size_t(g)])
              pos[I] = own_components(P::position, ev);
            else
              pos[I] = pos[std::size_t(from)] + own_components(P::position, ev);
          }(),
          ...);
    }(typename JF::all_points{}, std::make_index_sequence<np>{});
    static_for<nf>([&](auto f) {
      constexpr int o = t.origin[f];
      if constexpr (f == 0 || o == t.origin[std::size_t(t.parent[f])])
        offset[f] = zero;
      else
        offset[f] = pos[std::size_t(o)];
    });
  }
  // The position of the point P of an item of frame f from o_f, in f's components.
  template <int P, int Frame>
  KANE_ALWAYS_INLINE vec local() const {
    if constexpr (P < 0 || P == t.origin[std::size_t(Frame)])
      return {S(0), S(0), S(0)};
    else
      return pos[std::size_t(P)];
  }
};

}  // namespace kane::detail
