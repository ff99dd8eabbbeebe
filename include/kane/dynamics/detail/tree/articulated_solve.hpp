// X = -M^-1 X for many columns by articulated bodies in the root's components (spatial.hpp):
// every screw S_r and inertia is about O, so nothing turns. Once, inward from each frame's own
// items: U = I^A S, D = S.U, I^A of the parent += I^A - U U^T / D. Then for each column b,
// inward: u_r = b_r - S.p, p of the parent += p + U u_r / D; outward from a_O = 0:
// x_r = (u_r - U.a') / D, a = a' + S x_r. Cost: O(n) a column, against O(n^2) for a
// factored M. The columns go 2W at a time, each number two packets of W, then in packets of W, W / 2, ...
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
  // S and U / D also as packets of W equal numbers, below AVX-512 (there a product broadcasts a number
  // from memory itself)
  static constexpr bool spread = W > 1 && register_bytes < 64;
  static constexpr std::size_t B = spread ? W : 1;
  using wide = std::array<pack<B>, 6>;
  // packets of columns a pass carries side by side
  static constexpr std::size_t chains = 2;
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
  std::array<wide, n> sw_{}, uw_{};
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

  // x = -M^-1 x for each x, chains packets of W columns at a time, then packets of W, W / 2, ...
  template <class... X>
  void solve_negated(X&... x) const {
    (
        [&] {
          const auto cols = std::size_t(x.cols());
          std::size_t c0 = 0;
          for (; c0 + chains * W <= cols; c0 += chains * W) columns<W, chains>(x, c0);
          in_packets<W>(c0, cols, [&](std::size_t c, auto v) { columns<decltype(v)::value, 1>(x, c); });
        }(),
        ...);
  }

 private:
  // One number of K packets of V columns; a column pass is a chain of dependent products, so K
  // independent chains keep the multipliers busy.
  template <std::size_t V, std::size_t K>
  using lanes = std::array<pack<V>, K>;
  template <std::size_t V, std::size_t K>
  using rows = std::array<lanes<V, K>, 6>;
  template <class F>
  KANE_ALWAYS_INLINE static void each(F&& f) {
    static_for_inline<6>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { f(std::size_t(i)); });
  }
  template <std::size_t V, std::size_t K>
  KANE_ALWAYS_INLINE static rows<V, K> zeros() {
    rows<V, K> z;
    each([&](std::size_t i) KANE_ALWAYS_INLINE_LAMBDA {
      for (std::size_t k = 0; k < K; ++k) z[i][k] = splat<V>(S(0));
    });
    return z;
  }
  template <std::size_t V, std::size_t K>
  KANE_ALWAYS_INLINE static void add(rows<V, K>& to, const rows<V, K>& from) {
    each([&](std::size_t i) KANE_ALWAYS_INLINE_LAMBDA {
      for (std::size_t k = 0; k < K; ++k) to[i][k] += from[i][k];
    });
  }
  template <std::size_t V, std::size_t K, class A>  // c += a x
  KANE_ALWAYS_INLINE static void add_times(rows<V, K>& c, const A& a, const lanes<V, K>& x) {
    each([&](std::size_t i) KANE_ALWAYS_INLINE_LAMBDA {
      for (std::size_t k = 0; k < K; ++k) c[i][k] += a[i] * x[k];
    });
  }
  template <std::size_t V, std::size_t K, class A>
  KANE_ALWAYS_INLINE static lanes<V, K> dot(const A& a, const rows<V, K>& c) {
    lanes<V, K> out;
    for (std::size_t k = 0; k < K; ++k)
      out[k] = (a[0] * c[0][k] + a[1] * c[1][k]) + (a[2] * c[2][k] + a[3] * c[3][k]) +
               (a[4] * c[4][k] + a[5] * c[5][k]);
    return out;
  }
  // S (or U / D) of u_j for V columns: its packets when they are stored
  template <std::size_t V>
  KANE_ALWAYS_INLINE static const auto& of(const std::array<six, n>& one, const std::array<wide, n>& spread_,
                                           std::size_t j) {
    if constexpr (spread && V == W)
      return spread_[j];
    else
      return one[j];
  }
  template <std::size_t V, std::size_t K, class X>
  void columns(X& x, std::size_t c0) const {
    std::array<rows<V, K>, nf> p;  // p inward, then a outward, kept where the tree branches
    std::array<lanes<V, K>, n> ur;
    for (std::size_t g = 0; g < nf; ++g)
      if (shape.kept[g]) p[g] = zeros<V, K>();
    rows<V, K> c = zeros<V, K>();  // p of the frame after g when g is its parent, carried
    for (std::size_t g = nf - 1; g > 0; --g) {
      if (shape.kept[g]) add<V, K>(c, p[g]);
      const int r = t.speed[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        lanes<V, K> b;
        for (std::size_t k = 0; k < K; ++k) {
          std::array<S, V> row;
          for (std::size_t l = 0; l < V; ++l) row[l] = x(Eigen::Index(j), Eigen::Index(c0 + k * V + l));
          b[k] = load_packet<V>(row.data());
        }
        const lanes<V, K> sc = dot<V, K>(of<V>(s_, sw_, j), c);
        for (std::size_t k = 0; k < K; ++k) ur[j][k] = -b[k] - sc[k];
        add_times<V, K>(c, of<V>(ud_, uw_, j), ur[j]);
      }
      if (!shape.carried[g]) add<V, K>(p[std::size_t(t.parent[g])], c), c = zeros<V, K>();
    }
    c = zeros<V, K>(), p[0] = zeros<V, K>();  // a of the frame before g when it is g's parent; a_O = 0
    for (std::size_t g = 1; g < nf; ++g) {
      if (!shape.carried[g]) c = p[std::size_t(t.parent[g])];
      const int r = t.speed[g];
      if (r >= 0) {
        const auto j = std::size_t(r);
        const lanes<V, K> ua = dot<V, K>(of<V>(ud_, uw_, j), c);
        lanes<V, K> xr;
        for (std::size_t k = 0; k < K; ++k) {
          xr[k] = ur[j][k] * inv_d_[j] - ua[k];
          for (std::size_t l = 0; l < V; ++l) x(Eigen::Index(j), Eigen::Index(c0 + k * V + l)) = xr[k][l];
        }
        add_times<V, K>(c, of<V>(s_, sw_, j), xr);
      }
      if (shape.kept[g]) p[g] = c;
    }
  }
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
