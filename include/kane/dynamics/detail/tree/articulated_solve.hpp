// X = -M^-1 X for many columns by articulated bodies in the root's components (spatial.hpp):
// every screw S_r and inertia is about O, so nothing turns. Once, inward from each frame's own
// items: U = I^A S, D = S.U, I^A of the parent += I^A - U U^T / D. Then for each column b,
// inward: u_r = b_r - S.p, p of the parent += p + U u_r / D; outward from a_O = 0:
// x_r = (u_r - U.a') / D, a = a' + S x_r. Cost: O(n) a column, against O(n^2) for a
// factored M; the columns go W at a time, each number a packet of W, the rest in narrower packets.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/packet.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"
#include "kane/dynamics/detail/tree/spatial.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class JF, class S>
class articulated_solve {
  static constexpr auto& t = JF::table;
  static constexpr std::size_t nf = JF::nf, n = JF::n;
  static constexpr std::size_t W = packet_width<S>;
  using six = std::array<S, 6>;
  template <std::size_t V>
  using pack = packet<S, V>;  // one number of V columns
  template <std::size_t V>
  using rows = std::array<pack<V>, 6>;  // six components of V columns
  // S and U / D also as packets of W equal numbers, below AVX-512 (there a product broadcasts a number
  // from memory itself)
  static constexpr bool spread = W > 1 && register_bytes < 64;
  static constexpr std::size_t B = spread ? W : 1;
  // Frame g hands its sum to the next frame in registers when that frame is its parent (inward: g - 1;
  // outward: a child at g + 1); a frame with another child keeps its sum in memory.
  struct tree_shape {
    std::array<bool, nf> carried{}, kept{};
  };
  static constexpr tree_shape shape = [] {
    tree_shape z;
    for (std::size_t g = 1; g < nf; ++g) z.carried[g] = t.parent[g] == int(g) - 1;
    for (std::size_t g = 1; g < nf; ++g)
      if (!z.carried[g]) z.kept[std::size_t(t.parent[g])] = true;
    return z;
  }();
  std::array<six, n> s_{}, ud_{};  // S and U / D of each speed
  std::array<rows<B>, n> sw_{}, uw_{};
  std::array<S, n> inv_d_{};
  bool ok_ = true;

  static six flat(const spatial<S>& x) { return {x.w.x, x.w.y, x.w.z, x.v.x, x.v.y, x.v.z}; }
  // [I [h]; [h]^T m 1]
  static Eigen::Matrix<S, 6, 6> matrix(const composite_inertia<S>& y) {
    Eigen::Matrix<S, 6, 6> a;
    const S z(0);
    a << y.i[0], y.i[3], y.i[5], z, -y.h.z, y.h.y,  //
        y.i[3], y.i[1], y.i[4], y.h.z, z, -y.h.x,   //
        y.i[5], y.i[4], y.i[2], -y.h.y, y.h.x, z,   //
        z, y.h.z, -y.h.y, y.mass, z, z,             //
        -y.h.z, z, y.h.x, z, y.mass, z,             //
        y.h.y, -y.h.x, z, z, z, y.mass;
    return a;
  }

 public:
  articulated_solve(const std::array<composite_inertia<S>, nf>& own, const std::array<spatial<S>, n>& screw) {
    std::array<Eigen::Matrix<S, 6, 6>, nf> ia;
    for (std::size_t g = 0; g < nf; ++g) ia[g] = matrix(own[g]);
    for (std::size_t g = nf - 1; g > 0; --g) {
      const auto p = std::size_t(t.parent[g]);
      const int r = t.speed[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        const six sj = flat(screw[j]);
        const Eigen::Matrix<S, 6, 1> u = ia[g] * Eigen::Map<const Eigen::Matrix<S, 6, 1>>(sj.data());
        S d(0);
        for (std::size_t i = 0; i < 6; ++i) d += sj[i] * u(Eigen::Index(i));
        ok_ = ok_ && d > S(0);
        inv_d_[j] = S(1) / d, s_[j] = sj;
        for (std::size_t i = 0; i < 6; ++i) ud_[j][i] = inv_d_[j] * u(Eigen::Index(i));
        if constexpr (spread)
          for (std::size_t i = 0; i < 6; ++i) sw_[j][i] = splat<W>(s_[j][i]), uw_[j][i] = splat<W>(ud_[j][i]);
        ia[g].noalias() -= (inv_d_[j] * u) * u.transpose();
      }
      ia[p] += ia[g];
    }
  }
  // M is positive definite.
  bool ok() const { return ok_; }

  // x = -M^-1 x, W columns at a time, then W / 2, ...
  template <class X>
  void solve_negated(X& x) const {
    in_packets<W>(0, std::size_t(x.cols()),
                  [&](std::size_t c0, auto v) { columns<decltype(v)::value>(x, c0); });
  }

 private:
  template <std::size_t V>
  KANE_ALWAYS_INLINE static rows<V> zeros() {
    rows<V> z;
    static_for_inline<6>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { z[i] = splat<V>(S(0)); });
    return z;
  }
  template <std::size_t V>
  KANE_ALWAYS_INLINE static void add(rows<V>& to, const rows<V>& from) {
    static_for_inline<6>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { to[i] += from[i]; });
  }
  template <std::size_t V, class A>  // c += a x
  KANE_ALWAYS_INLINE static void add_times(rows<V>& c, const A& a, const pack<V>& x) {
    static_for_inline<6>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { c[i] += a[i] * x; });
  }
  template <std::size_t V, class A>
  KANE_ALWAYS_INLINE static pack<V> dot(const A& a, const rows<V>& c) {
    return (a[0] * c[0] + a[1] * c[1]) + (a[2] * c[2] + a[3] * c[3]) + (a[4] * c[4] + a[5] * c[5]);
  }
  // S (or U / D) of u_j for V columns: its packets when they are stored
  template <std::size_t V>
  KANE_ALWAYS_INLINE static const auto& of(const std::array<six, n>& one, const std::array<rows<B>, n>& wide,
                                           std::size_t j) {
    if constexpr (spread && V == W)
      return wide[j];
    else
      return one[j];
  }
  template <std::size_t V, class X>
  void columns(X& x, std::size_t c0) const {
    std::array<rows<V>, nf> p;  // p inward, then a outward, kept where the tree branches
    std::array<pack<V>, n> ur;
    for (std::size_t g = 0; g < nf; ++g)
      if (shape.kept[g]) p[g] = zeros<V>();
    rows<V> c = zeros<V>();  // p of the frame after g when g is its parent, carried
    for (std::size_t g = nf - 1; g > 0; --g) {
      if (shape.kept[g]) add<V>(c, p[g]);
      const int r = t.speed[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        pack<V> b{};
        for (std::size_t k = 0; k < V; ++k) b[k] = x(Eigen::Index(j), Eigen::Index(c0 + k));
        ur[j] = -b - dot<V>(of<V>(s_, sw_, j), c);
        add_times<V>(c, of<V>(ud_, uw_, j), ur[j]);
      }
      if (!shape.carried[g]) add<V>(p[std::size_t(t.parent[g])], c), c = zeros<V>();
    }
    c = zeros<V>(), p[0] = zeros<V>();  // a of the frame before g when it is g's parent, carried; a_O = 0
    for (std::size_t g = 1; g < nf; ++g) {
      if (!shape.carried[g]) c = p[std::size_t(t.parent[g])];
      const int r = t.speed[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        const pack<V> xr = ur[j] * inv_d_[j] - dot<V>(of<V>(ud_, uw_, j), c);
        for (std::size_t k = 0; k < V; ++k) x(Eigen::Index(j), Eigen::Index(c0 + k)) = xr[k];
        add_times<V>(c, of<V>(s_, sw_, j), xr);
      }
      if (shape.kept[g]) p[g] = c;
    }
  }
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
