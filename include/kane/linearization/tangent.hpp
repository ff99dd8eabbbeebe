// Linearization in the tangent space of Euler-parameter attitudes: each frame turned by Euler
// parameters e = (e0, e1, e2, e3), scalar first, is perturbed by a rotation vector dtheta in its own
// axes, e = e* (1, dtheta / 2) (a product of quaternions), so that
//   de = G(e*) dtheta,   G(e) = 1/2 [-e1 -e2 -e3; e0 -e3 e2; e3 e0 -e1; -e2 e1 e0],
// and a free body has 12 states, not 13: A has no direction along |e| (LQR, estimators).
//
//   auto lin = kane::linearize_tangent<Sys, Ev, kane::inputs<...>>(s);
//   x~ = (q, u), each frame's four Euler parameters replaced by dtheta at the place of e0
//
// With dx = T dx~ (G at each attitude, 1 elsewhere) and L = 4 G^T (L G = 1 for |e*| = 1),
// A~ = L (A T - T') and B~ = L B, where T' holds G(e*') of the rates x' at s (zero at rest).
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "kane/detail/list.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/linearization/attitude_map.hpp"
#include "kane/linearization/linearize.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The Euler parameters of the frames of a closure: their coordinates (1-based), and where each
// coordinate goes in x~ (the first of a set to three entries, the others to none).
template <std::size_t NQ>
struct tangent_layout {
  std::array<std::array<std::size_t, 4>, NQ> sets{};
  std::size_t count = 0;
  std::array<std::size_t, NQ> set_of{};  // 1 + the set of q_i, or 0
  std::size_t n = NQ;                    // the coordinates of x~
};
template <std::size_t NQ, class... F>
constexpr tangent_layout<NQ> tangent_layout_of(list<F...>) {
  tangent_layout<NQ> out;
  (
      [&] {
        if constexpr (euler_edge<F>) {
          constexpr auto c = F::step::coordinates;
          out.sets[out.count++] = c;
          for (std::size_t i : c) out.set_of[i - 1] = out.count;
          out.n -= 1;
        }
      }(),
      ...);
  return out;
}
}  // namespace detail

// dx~' = A dx~ + B dr with Euler-parameter attitudes as rotation vectors in their own axes.
template <class S, std::size_t NX, std::size_t NR>
struct tangent_model {
  // A~ = dx~'/dx~
  Eigen::Matrix<S, int(NX), int(NX)> A;
  // B~ = dx~'/dr
  Eigen::Matrix<S, int(NX), int(NR)> B;
  // the status of the equations at the state
  solve_status status;
};

// A~ and B~ of x~ = (q with each attitude as a rotation vector, u) at s.
template <System Sys, Evaluator Ev, class In = inputs<>>
auto linearize_tangent(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t nq = Ev::state_type::nq, nu = Ev::nu, nx = nq + nu;
  constexpr auto layout = detail::tangent_layout_of<nq>(typename Ev::closure{});
  constexpr std::size_t n = layout.n + nu;
  const auto lin = linearize<Sys, Ev, In>(s);
  // A T - T' by columns, then L by rows: T and L are 1 but for each attitude's G and L = 4 G^T / |e|^2
  Eigen::Matrix<S, int(nx), int(n)> at;
  tangent_model<S, n, In::n> out;
  Eigen::Index col = 0;
  for (std::size_t i = 0; i < nq; ++i) {
    const std::size_t k = layout.set_of[i];
    if (k == 0)
      at.col(col++) = lin.A.col(Eigen::Index(i));
    else if (layout.sets[k - 1][0] == i + 1) {  // the scalar part's place holds dtheta
      const auto& c = layout.sets[k - 1];
      const auto rate = [&](std::size_t a) { return S(lin.rate(Eigen::Index(c[a] - 1))); };
      const Eigen::Matrix<S, 4, 3> g = detail::attitude_map(S(s.q[c[0] - 1]), S(s.q[c[1] - 1]),
                                                            S(s.q[c[2] - 1]), S(s.q[c[3] - 1])),
                                   gd = detail::attitude_map(rate(0), rate(1), rate(2), rate(3));
      Eigen::Matrix<S, int(nx), 4> four;
      for (std::size_t a = 0; a < 4; ++a) four.col(Eigen::Index(a)) = lin.A.col(Eigen::Index(c[a] - 1));
      at.template middleCols<3>(col).noalias() = four * g;
      for (std::size_t a = 0; a < 4; ++a)
        at.row(Eigen::Index(c[a] - 1)).template segment<3>(col) -= gd.row(Eigen::Index(a));
      col += 3;
    }
  }
  at.template rightCols<int(nu)>() = lin.A.template rightCols<int(nu)>();
  const auto rows = [&](const auto& x, auto& y) {  // y = L x
    Eigen::Index row = 0;
    for (std::size_t i = 0; i < nq; ++i) {
      const std::size_t k = layout.set_of[i];
      if (k == 0)
        y.row(row++) = x.row(Eigen::Index(i));
      else if (layout.sets[k - 1][0] == i + 1) {
        const auto& c = layout.sets[k - 1];
        const Eigen::Matrix<S, 4, 1> e(s.q[c[0] - 1], s.q[c[1] - 1], s.q[c[2] - 1], s.q[c[3] - 1]);
        const Eigen::Matrix<S, 4, 3> g = detail::attitude_map(e(0), e(1), e(2), e(3));
        const S scale = S(4) / e.squaredNorm();  // L G = 1 for e of any norm
        for (Eigen::Index b = 0; b < 3; ++b) {
          y.row(row + b) = scale * g(0, b) * x.row(Eigen::Index(c[0] - 1));
          for (std::size_t a = 1; a < 4; ++a)
            y.row(row + b) += scale * g(Eigen::Index(a), b) * x.row(Eigen::Index(c[a] - 1));
        }
        row += 3;
      }
    }
    y.template bottomRows<int(nu)>() = x.template bottomRows<int(nu)>();
  };
  rows(at, out.A), rows(lin.B, out.B);
  out.status = lin.status;
  return out;
}

}  // namespace kane
#pragma GCC diagnostic pop
