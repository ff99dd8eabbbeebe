// The table of a system of joint form (joint_form.hpp): indices of frames, points, items and
// speeds in constexpr arrays, and the body coordinates' origins (body_frames.hpp).
#pragma once

#include <array>
#include <cstddef>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// What the recursive sums need of the items of a system, in a tree of NF frames, NP points, NI
// items and N speeds.
template <std::size_t NF, std::size_t NP, std::size_t NI, std::size_t N>
struct joint_table {
  bool holds = false;
  std::array<int, NF> parent{};       // index of the tree parent (-1: the root)
  std::array<int, NF> speed{};        // r (from 0) of the edge's u_r = q_c' (-1: a constant edge)
  std::array<int, NP> from{};         // index of the predecessor point (-1: the origin)
  std::array<int, NP> segment{};      // frame of the vector to the point (-1: none)
  std::array<int, NP> attach{};       // the deepest frame of the point's chain (0: the root)
  std::array<int, NI> item_frame{};   // the frame whose edges move the item (-1: not moved)
  std::array<int, NI> item_point{};   // its point (-1: none)
  std::array<int, N> joint_frame{};   // the frame turned by u_r
  std::array<int, N> joint_point{};   // X_r, a point index (-1: no point below the edge)
  std::array<int, N> parent_speed{};  // the nearest speed above u_r's edge (-1: none)
  // A free joint (speed_layout.hpp): its frame, a child of the root, moved by u_1..u_6 about its
  // origin X_1, the point at position_coordinates (-1: none). Its edge's speed is -1.
  int free = -1;
  // Body coordinates: every frame F has an origin o_F (X_r of its edge, its parent's for a
  // constant edge, O for the root); every point P is located from o_G in G's components
  // (G = frame[P]); o_F from o_P in P's, an item of F from o_F in F's.
  bool local = false;
  std::array<int, NF> origin{};
  std::array<int, NP> frame{};

  std::array<int, NF> depth{};  // edges from the root

  constexpr bool below(int f, int g) const {  // g is f or an ancestor of f
    if (f < 0 || g < 0) return false;
    while (depth[std::size_t(f)] > depth[std::size_t(g)]) f = parent[std::size_t(f)];
    return f == g;
  }
};

template <class T>
constexpr bool local_origins(T& t) {
  bool ok = true;
  for (std::size_t f = 1; f < t.origin.size(); ++f) {
    const int r = int(f) == t.free ? 0 : t.speed[f];
    t.origin[f] = r >= 0 ? t.joint_point[std::size_t(r)] : t.origin[std::size_t(t.parent[f])];
    ok = ok && t.origin[f] >= 0;
  }
  for (std::size_t p = 0; p < t.frame.size() && ok; ++p) {
    const int from = t.from[p], g = t.segment[p];
    if (from < 0)
      t.frame[p] = 0;
    else if (g < 0)
      t.frame[p] = t.frame[std::size_t(from)];
    else {
      ok = from == t.origin[std::size_t(g)] || t.frame[std::size_t(from)] == g;
      t.frame[p] = g;
    }
  }
  for (std::size_t f = 1; f < t.origin.size() && ok; ++f) {
    const int o = t.origin[f], op = t.origin[std::size_t(t.parent[f])];
    ok = o == op || t.frame[std::size_t(o)] == t.parent[f];
  }
  for (std::size_t i = 0; i < t.item_frame.size() && ok; ++i) {
    const int f = t.item_frame[i], p = t.item_point[i];
    ok = f <= 0 || p < 0 || p == t.origin[std::size_t(f)] || t.frame[std::size_t(p)] == f;
  }
  return ok;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
