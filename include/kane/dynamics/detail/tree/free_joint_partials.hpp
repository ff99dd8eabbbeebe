// The rows and columns of a free joint in the derivatives' passes (rnea_derivatives.hpp).
// A free joint (speed_layout.hpp) is a child of the root moved by u_1..u_6: S_1..3 = (b_i, p x b_i)
// about its origin p, S_4..6 = (0, r_i). Its q-directions are a rotation vector in B's axes and p:
// a change of theta_j turns every item below B and S_1..3 with them, not v^- = (0, p'), a^- =
// a_O + (0, p''); so dV_j = v^- x S_j for j = 1..3, 0 for j = 4..6, and every pair of S_1..3 takes
// the form of u_j at or above u_r (rnea_derivatives.hpp). The rates are body rates, so dtau/du_j (j = 1..3)
// also takes Y (v_w x S_j), v_w = S_1 u_1 + S_2 u_2 + S_3 u_3. A uniform shift of p or p' changes nothing:
// those columns are 0. Column r is the derivative along the motion of u_r.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/rnea.hpp"
#include "kane/dynamics/detail/tree/spatial.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The free joint's frame g, outward from the root at rest: v^- = (0, p'), a^- = a_O + (0, p'').
template <class P, class Ev, class Rates>
KANE_ALWAYS_INLINE void free_outward(P& p, const Ev& ev, const Rates& ud, std::size_t g) {
  using S = typename P::S;
  using vec = v3<S>;
  const vec zero{S(0), S(0), S(0)};
  const spatial<S> vt{zero, vec{joint_rate<1>(ev, 3), joint_rate<1>(ev, 4), joint_rate<1>(ev, 5)}};
  const spatial<S> ac{p.a[0].w,
                      p.a[0].v + vec{S(ud(Eigen::Index(3))), S(ud(Eigen::Index(4))), S(ud(Eigen::Index(5)))}};
  spatial<S> vw{zero, zero};
  p.v[g] = vt, p.a[g] = ac;
  for (std::size_t i = 0; i < 3; ++i) {
    const spatial<S>& s = p.screw[i];
    const S u = joint_rate<1>(ev, i);
    p.dv[i] = cross_motion(vt, s), p.da[i] = cross_motion(ac, s) + cross_motion(vt, p.dv[i]);
    p.dv[3 + i] = {zero, zero}, p.da[3 + i] = {zero, zero};
    vw = vw + u * s;
    p.a[g] = p.a[g] + S(ud(Eigen::Index(i))) * s + u * p.dv[i];
  }
  p.v[g] = p.v[g] + vw;
  for (std::size_t i = 0; i < 3; ++i) p.turned[i] = cross_motion(vw, p.screw[i]);
}
// Rows and columns 1..6 at the free joint's frame g, Y, B and F summed below it: rows 1..3 take the
// form of u_j at or above u_r for columns 1..3 (S_1..3 turn with each other), rows 4..6 the form of
// u_j above it.
template <bool Mass, class P, class Tau, class Square>
KANE_ALWAYS_INLINE void free_inward(const P& p, std::size_t g, Tau& tau, Square& m, Square& dq, Square& du) {
  using S = typename P::S;
  using vec = v3<S>;
  std::array<spatial<S>, 6> ys;
  std::array<vec, 3> bs;
  for (std::size_t r = 0; r < 6; ++r) {
    ys[r] = times(p.own[g], p.screw[r]), tau(Eigen::Index(r)) = dot6(p.screw[r], p.f[g]);
    if (r < 3) bs[r] = p.b[g].transposed_times(p.screw[r]);
    if constexpr (Mass)
      for (std::size_t c = 0; c <= r; ++c)
        m(Eigen::Index(r), Eigen::Index(c)) = m(Eigen::Index(c), Eigen::Index(r)) = dot6(ys[r], p.screw[c]);
  }
  for (std::size_t c = 0; c < 3; ++c) {
    const auto l = Eigen::Index(c);
    const spatial<S> wu = S(2) * p.dv[c] + p.turned[c];
    for (std::size_t r = 0; r < 3; ++r) {
      const auto k = Eigen::Index(r);
      dq(k, l) = dot6(ys[r], p.da[c]) + dot3(bs[r], p.dv[c].w);
      du(k, l) = dot6(ys[r], wu) + dot3(bs[r], p.screw[c].w);
    }
    const spatial<S> fq = times(p.own[g], p.da[c]) + p.b[g].times(p.dv[c]) + cross_force(p.screw[c], p.f[g]);
    const spatial<S> fu = times(p.own[g], wu) + p.b[g].times(p.screw[c]);
    for (std::size_t r = 3; r < 6; ++r)
      dq(Eigen::Index(r), l) = dot6(p.screw[r], fq), du(Eigen::Index(r), l) = dot6(p.screw[r], fu);
  }
  for (Eigen::Index c = 3; c < 6; ++c)
    for (Eigen::Index r = 0; r < 6; ++r) dq(r, c) = du(r, c) = S(0);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
