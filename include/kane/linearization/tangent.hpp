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
  Eigen::Matrix<S, int(nx), int(n)> t = Eigen::Matrix<S, int(nx), int(n)>::Zero(), td = t;
  Eigen::Matrix<S, int(n), int(nx)> l = Eigen::Matrix<S, int(n), int(nx)>::Zero();
  Eigen::Index col = 0;
  for (std::size_t i = 0; i < nq; ++i) {
    const std::size_t k = layout.set_of[i];
    if (k == 0) {
      t(Eigen::Index(i), col) = l(col, Eigen::Index(i)) = S(1);
      ++col;
    } else if (layout.sets[k - 1][0] == i + 1) {  // the scalar part's place holds dtheta
      const auto& c = layout.sets[k - 1];
      const auto at = [&](const auto& x, std::size_t a) { return S(x(Eigen::Index(c[a] - 1))); };
      const Eigen::Matrix<S, 4, 1> e(s.q[c[0] - 1], s.q[c[1] - 1], s.q[c[2] - 1], s.q[c[3] - 1]);
      const Eigen::Matrix<S, 4, 3> g = detail::attitude_map(e(0), e(1), e(2), e(3)),
                                   gd = detail::attitude_map(at(lin.rate, 0), at(lin.rate, 1),
                                                             at(lin.rate, 2), at(lin.rate, 3));
      const S norm2 = e.squaredNorm();  // L G = 1 for e of any norm: L = 4 G^T / |e|^2
      for (std::size_t a = 0; a < 4; ++a)
        for (Eigen::Index b = 0; b < 3; ++b) {
          t(Eigen::Index(c[a] - 1), col + b) = g(Eigen::Index(a), b);
          td(Eigen::Index(c[a] - 1), col + b) = gd(Eigen::Index(a), b);
          l(col + b, Eigen::Index(c[a] - 1)) = S(4) * g(Eigen::Index(a), b) / norm2;
        }
      col += 3;
    }
  }
  for (std::size_t j = 0; j < nu; ++j)
    t(Eigen::Index(nq + j), col + Eigen::Index(j)) = l(col + Eigen::Index(j), Eigen::Index(nq + j)) = S(1);
  tangent_model<S, n, In::n> out;
  out.A = l * (lin.A * t - td);
  out.B = l * lin.B;
  out.status = lin.status;
  return out;
}

}  // namespace kane
#pragma GCC diagnostic pop
