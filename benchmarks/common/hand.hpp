// What the hand-written baselines of the chains share (arm6_hand.cpp, chain_hand.cpp):
// three plain doubles per vector, the frame's axes as three of them, rotations about a
// principal axis, and joints unrolled at compile time so that every axis index is a constant.
#pragma once

#include <cmath>
#include <utility>

namespace hand {
struct v3 {
  double x, y, z;
};
inline v3 operator+(v3 a, v3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline v3 operator-(v3 a, v3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline v3 operator*(double s, v3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline v3& operator+=(v3& a, v3 b) { return a = a + b; }
inline v3 cross(v3 a, v3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline void store(v3 a, double* out) { out[0] = a.x, out[1] = a.y, out[2] = a.z; }

// A body's axes b1, b2, b3 expressed in N: the columns of ^N R^B.
struct axes {
  v3 e[3];
};
// The first joint turns about n3 from N: its axes in closed form.
inline axes about_z(double c, double s) { return {{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}}; }
// Turns R about its own axis k: e_a' = c e_a + s e_b, e_b' = c e_b - s e_a; e_k stays.
template <int k>
inline void turn(axes& R, double c, double s) {
  constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
  const v3 ea = R.e[a], eb = R.e[b];
  R.e[a] = c * ea + s * eb;
  R.e[b] = c * eb - s * ea;
}
// sin and cos of the first n joints, all before any arithmetic: every xmm register is
// caller-saved, so a call in the middle of the pass would spill everything live across it.
template <int n>
struct trig {
  double c[n], s[n];
  template <class Q>
  explicit trig(const Q& q) {
    for (int i = 0; i < n; ++i) c[i] = std::cos(q[i]), s[i] = std::sin(q[i]);
  }
};
// body(I) for I = From .. To-1, each I a compile-time constant.
template <int From, int To, class Body>
inline void joints(Body body) {
  [&]<int... I>(std::integer_sequence<int, I...>) { (body(std::integral_constant<int, From + I>{}), ...); }
  (std::make_integer_sequence<int, To - From>{});
}

// Everything for n joints (R, p, w, v, alpha, a, and the 6 x n Jacobian column-major) in one outward
// pass that shares the rotations, the axes k_i, the links r_i and w x r_i: sin and cos first, joint 1
// in closed form, two columns turned per joint, then Jacobian columns k_i x (r_i + ... + r_n) summed
// backwards (0 for the last when its axis is its link's). Model::axis(i), Model::length(i) are
// constexpr. Flattened: g++ would otherwise leave joints of the 20-joint chain out of line.
template <int n, class Model, class In, class Out>
[[gnu::flatten]] inline void outward_pass(const In& q, const In& qd, const In& qdd, Out& out) {
  constexpr auto axis = Model::axis;
  constexpr auto length = Model::length;
  static_assert(axis(0) == 2, "joint 1 turns about n3");
  const trig<n> t(q);
  v3 k[n], r[n];
  const double L0 = length(0);
  axes R = about_z(t.c[0], t.s[0]);
  k[0] = {0, 0, 1};
  r[0] = {L0 * t.c[0], L0 * t.s[0], 0};
  v3 p = r[0], w{0, 0, qd[0]}, al{0, 0, qdd[0]};
  const v3 n3r = {-r[0].y, r[0].x, 0};  // n3 x r_1
  v3 v = qd[0] * n3r;
  v3 a = {qdd[0] * n3r.x - qd[0] * qd[0] * r[0].x, qdd[0] * n3r.y - qd[0] * qd[0] * r[0].y, 0};
  joints<1, n>([&](auto I) {
    constexpr int ax = axis(I);
    const v3 kI = R.e[ax];
    k[I] = kI;
    al += qdd[I] * kI + qd[I] * cross(w, kI);
    w += qd[I] * kI;
    turn<ax>(R, t.c[I], t.s[I]);
    const v3 rI = length(I) * R.e[0];
    r[I] = rI;
    p += rI;
    const v3 wr = cross(w, rI);
    v += wr;
    a += cross(al, rI) + cross(w, wr);
  });
  v3 d = r[n - 1];
  store(k[n - 1], out.J + 6 * (n - 1));
  if constexpr (axis(n - 1) == 0)  // the last axis lies along its link: k_n x d_n = 0
    store({0, 0, 0}, out.J + 6 * (n - 1) + 3);
  else
    store(cross(k[n - 1], d), out.J + 6 * (n - 1) + 3);
  for (int i = n - 2; i >= 0; --i) {
    d += r[i];
    store(k[i], out.J + 6 * i);
    store(cross(k[i], d), out.J + 6 * i + 3);
  }
  for (int j = 0; j < 3; ++j) store(R.e[j], out.R + 3 * j);
  store(p, out.p);
  store(w, out.w);
  store(v, out.v);
  store(al, out.alpha);
  store(a, out.a);
}
}  // namespace hand
