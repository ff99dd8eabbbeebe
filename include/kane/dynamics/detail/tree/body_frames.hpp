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
#include "kane/dynamics/detail/tree/fixed_vectors.hpp"
#include "kane/dynamics/detail/tree/joint_form.hpp"
#include "kane/dynamics/detail/tree/turns.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/frames/axis.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

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

// Each point's own vector (from its predecessor): pattern, known or not, value if known.
template <class V>
constexpr std::array<double, 3> known_or_zero(const V& v) {
  if constexpr (known_vector<V>())
    return known_components(v);
  else
    return {0, 0, 0};
}
template <class PL>
struct own_facts;
template <class... P>
struct own_facts<list<P...>> {
  static constexpr std::array<std::array<entry, 3>, sizeof...(P)> pattern{
      own_pattern<std::remove_cv_t<decltype(P::position)>>()...};
  static constexpr bool known =
      ((known_vector<std::remove_cv_t<decltype(P::position)>>() || translated<P>() != 0) &&
       ...);  // a free joint's origin: a frame's origin, never read
  static constexpr std::array<std::array<double, 3>, sizeof...(P)> value{known_or_zero(P::position)...};
};

template <class JF, class Ev, class Frames = typename JF::frame_list>
struct body_frames;
template <class JF, class Ev, class... F>
struct body_frames<JF, Ev, list<F...>> {
  using S = typename Ev::scalar;
  using vec = v3<S>;
  static constexpr auto& t = JF::table;
  static constexpr std::size_t nf = JF::nf, np = JF::np;

  using own = own_facts<typename JF::all_points>;
  // The pattern of each point from the origin of its frame, in its components.
  static constexpr auto pos_pattern = [] {
    std::array<std::array<entry, 3>, np> out{};
    for (std::size_t i = 0; i < np; ++i) {
      const int from = t.from[i], g = t.segment[i];
      if (from < 0)
        out[i] = {entry::zero, entry::zero, entry::zero};
      else if (g < 0)
        out[i] = out[std::size_t(from)];
      else if (from == t.origin[std::size_t(g)])
        out[i] = own::pattern[i];
      else
        for (std::size_t j = 0; j < 3; ++j)
          out[i][j] = out[std::size_t(from)][j] == entry::zero && own::pattern[i][j] == entry::zero
                          ? entry::zero
                          : entry::other;
    }
    return out;
  }();
  // Every point's position known at compile time, and the positions.
  static constexpr bool known_positions = own::known;
  static constexpr auto known_pos = [] {
    std::array<std::array<double, 3>, np> out{};
    for (std::size_t i = 0; i < np; ++i) {
      const int from = t.from[i], g = t.segment[i];
      if (from < 0)
        out[i] = {0, 0, 0};
      else if (g < 0)
        out[i] = out[std::size_t(from)];
      else if (from == t.origin[std::size_t(g)])
        out[i] = own::value[i];
      else
        for (std::size_t j = 0; j < 3; ++j) out[i][j] = out[std::size_t(from)][j] + own::value[i][j];
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

  // The coordinate axis each frame's edge turns about (-1: a general E).
  static constexpr std::array<int, nf> axes{turn_axis<F>()...};
  // The pattern of E_F v, v of pattern p
  static constexpr std::array<entry, 3> turned_pattern(std::size_t f, const std::array<entry, 3>& p) {
    constexpr const auto& axis = axes;
    if (axis[f] < 0) return all_zero(p) ? p : std::array<entry, 3>{entry::other, entry::other, entry::other};
    const auto a = std::size_t(axis[f]), b = (a + 1) % 3, d = (a + 2) % 3;
    std::array<entry, 3> out = p;
    if (p[b] != entry::zero || p[d] != entry::zero) out[b] = out[d] = entry::other;
    if (p[a] != entry::zero) out[a] = entry::other;
    return out;
  }

  std::tuple<turn<S, turn_axis<F>()>...> e;  // e[0], the root's, unused
  std::array<vec, np> pos;                   // P from o of its frame, in its components
  std::array<vec, nf> offset;                // t_F

  KANE_ALWAYS_INLINE explicit body_frames(const Ev& ev)
      : e{[&]() KANE_ALWAYS_INLINE_LAMBDA {
          if constexpr (std::is_void_v<typename F::tree_parent>)
            return turn<S, -1>{};
          else
            return make_turn<F>(ev);
        }()...} {
    const vec zero{S(0), S(0), S(0)};
    [&]<class... P, std::size_t... I>(list<P...>, std::index_sequence<I...>) KANE_ALWAYS_INLINE_LAMBDA {
      (
          [&]() KANE_ALWAYS_INLINE_LAMBDA {
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
    static_for<nf>([&](auto f) KANE_ALWAYS_INLINE_LAMBDA {
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
#pragma GCC diagnostic pop
