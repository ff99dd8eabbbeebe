// Hand-written, as tight as we can write it: everything in body coordinates about the joint
// origins O_i, where link i's inertia (m, h = m c, J about O_i) is a constant of the tables.
// M by the composite-rigid-body algorithm, h and tau by recursive Newton-Euler (gravity as a
// base acceleration g n3). Indices from 0: joint i turns link i by q[i] about the coordinate
// axis k_i of link i - 1 (of N for i = 0), so each change of frame turns two components (two
// of J by 2q), and O_i+1 = O_i + L_i b_i x shifts by x only. q[0] turns about gravity and
// appears nowhere: sin and cos of q[1] .. q[5], once, before any arithmetic. q'' by Eigen's
// fixed-size LLT; tau by the same RNEA with q''.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>
#include <utility>

#include "dynamics6.hpp"

namespace {
using dynamics6::L;
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};  // z, y, y, x, y, x

struct v3 {
  double x[3];
};
// A symmetric J as J11, J22, J33, J12, J23, J31 (the table's order).
constexpr int sym(int i, int j) { return i == j ? i : j == (i + 1) % 3 ? 3 + i : 3 + j; }
struct body {
  double m;
  v3 h;  // m c, c the mass centre from the origin
  double J[6];
};
// Link i about O_i: h = m (L_i / 2) b_i x, J = J_c + m |c|^2 (b_i y b_i y + b_i z b_i z).
constexpr body link(int i) {
  const double m = dynamics6::mass[i], c = L[i] / 2;
  const double* j = dynamics6::inertia[i];
  return {m, {{m * c, 0, 0}}, {j[0], j[1] + m * c * c, j[2] + m * c * c, j[3], j[4], j[5]}};
}
constexpr body links[6] = {link(0), link(1), link(2), link(3), link(4), link(5)};

// sin and cos of q_i, and cos 2q_i, sin 2q_i, for i = 1 .. 5; the calls in the order
// the arithmetic needs them (the CRBA from the tip, the RNEA from the base), so that it starts
// under the last of them.
struct trig {
  double c[6], s[6], c2[6], s2[6];
  trig(const dynamics6::input& in, bool tip_first) {
    for (int r = 0; r < 5; ++r) {
      const int i = tip_first ? 5 - r : 1 + r;
      c[i] = std::cos(in.q[i]), s[i] = std::sin(in.q[i]);
    }
    for (int i = 1; i < 6; ++i) c2[i] = c[i] * c[i] - s[i] * s[i], s2[i] = 2 * c[i] * s[i];
  }
};

template <int I, class F>
inline void for_each(F f) {  // f(0) .. f(I-1), each index a constant
  [&]<int... i>(std::integer_sequence<int, i...>) { (f(std::integral_constant<int, i>{}), ...); }
  (std::make_integer_sequence<int, I>{});
}

// E_i u and E_i^T u: E_i turns body i's components into its parent's, about axis k.
template <int k>
inline v3 up(const v3& u, double c, double s) {
  constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
  v3 r;
  r.x[k] = u.x[k], r.x[a] = c * u.x[a] - s * u.x[b], r.x[b] = s * u.x[a] + c * u.x[b];
  return r;
}
template <int k>
inline v3 down(const v3& u, double c, double s) {
  return up<k>(u, c, -s);
}

// Composite i + 1 (m, h, J about O_i+1) turned by E_i+1 and shifted to O_i = O_i+1 - L_i b_i x:
// h += m L x; J += (2 L h_x + m L^2)(yy + zz) - L h_y (xy + yx) - L h_z (xz + zx), then added to link i.
// AlongX: the child's h lies along its x (composites 5 and 4), so E h has at most two components.
template <int i, bool AlongX = false>
inline body composite(const body& child, const trig& t) {
  constexpr int k = axis[i + 1], a = (k + 1) % 3, b = (k + 2) % 3;
  const double c = t.c[i + 1], s = t.s[i + 1], c2 = t.c2[i + 1], s2 = t.s2[i + 1];
  const double* j = child.J;
  double J[6];
  J[k] = j[k];
  const double mean = (j[a] + j[b]) / 2, half = (j[a] - j[b]) / 2;  // J_aa, J_bb, J_ab by 2q
  const double d = c2 * half - s2 * j[sym(a, b)];
  J[a] = mean + d, J[b] = mean - d, J[sym(a, b)] = s2 * half + c2 * j[sym(a, b)];
  J[sym(k, a)] = c * j[sym(k, a)] - s * j[sym(k, b)], J[sym(k, b)] = s * j[sym(k, a)] + c * j[sym(k, b)];
  v3 h{{0, 0, 0}};
  if constexpr (!AlongX)
    h = up<k>(child.h, c, s);
  else if constexpr (k == 0)
    h.x[0] = child.h.x[0];
  else  // x = a (k = 2) or b (k = 1)
    h.x[0] = c * child.h.x[0], h.x[k == 2 ? b : a] = (k == 2 ? s : -s) * child.h.x[0];
  const double m = child.m, l = L[i], shift = l * (2 * h.x[0] + m * l);
  constexpr body p = links[i];
  return {p.m + m,
          {{p.h.x[0] + h.x[0] + m * l, h.x[1], h.x[2]}},
          {p.J[0] + J[0], p.J[1] + J[1] + shift, p.J[2] + J[2] + shift, p.J[3] + J[3] - l * h.x[1],
           p.J[4] + J[4], p.J[5] + J[5] - l * h.x[2]}};
}

// M by CRBA: column i is S_j . X_j^i (I_i^c S_i), the force (n, f) = (J e_k, e_k x h) of composite i
// carried inward: n <- E n + L x x (E f), f <- E f. Out of line: inlined into hand_mass, g++ 12
// schedules it worse (-O3 -march=native: 95 ns against 84).
[[gnu::noinline]] void mass_matrix(const trig& t, double* M) {
  body C[6];
  C[5] = links[5];
  C[4] = composite<4, true>(C[5], t);
  C[3] = composite<3, true>(C[4], t);
  C[2] = composite<2>(C[3], t);
  C[1] = composite<1>(C[2], t);
  C[0] = composite<0>(C[1], t);
  for_each<6>([&](auto i) {
    constexpr int k = axis[i], a = (k + 1) % 3, b = (k + 2) % 3;
    const double* J = C[i].J;
    const v3& h = C[i].h;
    v3 n{{J[sym(0, k)], J[sym(1, k)], J[sym(2, k)]}}, f;
    f.x[k] = 0, f.x[a] = -h.x[b], f.x[b] = h.x[a];
    M[7 * i] = n.x[k];
    for_each<i>([&](auto r) {
      constexpr int j = i - 1 - r, kj = axis[j + 1];
      const double c = t.c[j + 1], s = t.s[j + 1];
      n = up<kj>(n, c, s);
      if constexpr (i != 5) {  // composite 5 has h along its axis x: f = 0
        f = up<kj>(f, c, s);
        n.x[1] -= L[j] * f.x[2], n.x[2] += L[j] * f.x[1];
      }
      M[6 * i + j] = M[6 * j + i] = n.x[axis[j]];
    });
  });
}

// RNEA in body coordinates: outward w, alpha and a of O_i, and the force and moment about O_i that link i
// needs, then inward sums; tau_i = n_i . e_k. A point at x b_i x accelerates by a + x u with
// u = alpha x e_x + w x (w x e_x), and h = h_x e_x: f = m a + h_x u, n = J alpha + w x J w + h_x e_x x a.
// Link 0 has w = q'_0 n3, alpha = q''_0 n3, a = g n3 (gravity as the base's acceleration): joint 1 (about
// y) turns them in closed form, and link 0's own moment about n3 is J33 q''_0.
template <bool Accelerating>
inline void newton_euler(const dynamics6::input& in, const trig& t, double* tau) {
  static_assert(axis[0] == 2 && axis[1] == 1);
  v3 F[6], N[6], w, al, a, u;
  for_each<5>([&](auto r) {
    constexpr int i = r + 1, k = axis[i], ka = (k + 1) % 3, kb = (k + 2) % 3;
    const double l = L[i - 1], c = t.c[i], s = t.s[i], qd = in.qd[i];
    if constexpr (i == 1) {
      const double w0 = in.qd[0], q0 = Accelerating ? in.qdd_in[0] : 0, lw = l * w0 * w0;
      a = {{-s * dynamics6::g - c * lw, l * q0, c * dynamics6::g - s * lw}};
      w = {{-s * w0, qd, c * w0}};
      al = {{-c * w0 * qd, 0, -s * w0 * qd}};
      if constexpr (Accelerating) al.x[0] -= s * q0, al.x[1] = in.qdd_in[1], al.x[2] += c * q0;
    } else {  // a_i = E^T (a + l u), w_i = E^T w + q' e_k, alpha_i = E^T alpha + (E^T w) x e_k q' + q'' e_k
      a = down<k>({{a.x[0] + l * u.x[0], a.x[1] + l * u.x[1], a.x[2] + l * u.x[2]}}, c, s);
      const v3 wd = down<k>(w, c, s);
      al = down<k>(al, c, s);
      al.x[ka] += qd * wd.x[kb], al.x[kb] -= qd * wd.x[ka];
      if constexpr (Accelerating) al.x[k] += in.qdd_in[i];
      w = wd;
      w.x[k] += qd;
    }
    u = {{-(w.x[1] * w.x[1] + w.x[2] * w.x[2]), al.x[2] + w.x[0] * w.x[1], w.x[0] * w.x[2] - al.x[1]}};
    constexpr body p = links[i];
    constexpr double m = p.m, hx = p.h.x[0];
    const double* J = p.J;
    F[i] = {{m * a.x[0] + hx * u.x[0], m * a.x[1] + hx * u.x[1], m * a.x[2] + hx * u.x[2]}};
    const v3 jw{{J[0] * w.x[0] + J[3] * w.x[1] + J[5] * w.x[2], J[3] * w.x[0] + J[1] * w.x[1] + J[4] * w.x[2],
                 J[5] * w.x[0] + J[4] * w.x[1] + J[2] * w.x[2]}};
    N[i] = {
        {J[0] * al.x[0] + J[3] * al.x[1] + J[5] * al.x[2] + w.x[1] * jw.x[2] - w.x[2] * jw.x[1],
         J[3] * al.x[0] + J[1] * al.x[1] + J[4] * al.x[2] + w.x[2] * jw.x[0] - w.x[0] * jw.x[2] - hx * a.x[2],
         J[5] * al.x[0] + J[4] * al.x[1] + J[2] * al.x[2] + w.x[0] * jw.x[1] - w.x[1] * jw.x[0] +
             hx * a.x[1]}};
  });
  v3 f = F[5], n = N[5];  // carried inward: the sums over links i .. 6 about O_i
  tau[5] = n.x[axis[5]];
  for_each<5>([&](auto r) {  // link i + 1's sums turned by E_i+1 and shifted by L_i b_i x
    constexpr int i = 4 - r, k = axis[i + 1];
    const double c = t.c[i + 1], s = t.s[i + 1], l = L[i];
    const v3 fc = up<k>(f, c, s), nc = up<k>(n, c, s);
    if constexpr (i == 0) {
      tau[0] = nc.x[2] + l * fc.x[1];
      if constexpr (Accelerating) tau[0] += links[0].J[2] * in.qdd_in[0];
    } else {
      f = {{F[i].x[0] + fc.x[0], F[i].x[1] + fc.x[1], F[i].x[2] + fc.x[2]}};
      n = {{N[i].x[0] + nc.x[0], N[i].x[1] + nc.x[1] - l * fc.x[2], N[i].x[2] + nc.x[2] + l * fc.x[1]}};
      tau[i] = n.x[axis[i]];
    }
  });
}
}  // namespace

void dynamics6::hand_mass(const input& in, output& out) { mass_matrix(trig(in, true), out.M); }
void dynamics6::hand_bias(const input& in, output& out) {
  const trig t(in, false);  // the RNEA's outward pass first: it starts at joint 1
  newton_euler<false>(in, t, out.h);
  mass_matrix(t, out.M);
}
void dynamics6::hand_forward(const input& in, output& out) {
  hand_bias(in, out);
  const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(Eigen::Map<const Eigen::Matrix<double, 6, 6>>(out.M));
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(out.qdd) =
      -llt.solve(Eigen::Map<const Eigen::Matrix<double, 6, 1>>(out.h));
}
void dynamics6::hand_inverse(const input& in, output& out) {
  newton_euler<true>(in, trig(in, false), out.tau);
}
