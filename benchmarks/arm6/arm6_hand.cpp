// The hand-written outward pass for the 6-revolute chain (arm6.hpp), as tight as we can write
// it: plain doubles (hand.hpp), sin and cos once per joint and all before the arithmetic, joint 1
// in closed form, every other rotation on two columns, no Eigen. Joint 6 turns about b6 x, along
// which the end point lies: only the pose needs q6, and the last Jacobian column's v is 0.
#include "../common/hand.hpp"
#include "arm6.hpp"

namespace {
using namespace hand;
constexpr int axis[6] = {2, 1, 1, 0, 1, 0};
struct model {
  static constexpr int axis(int i) { return ::axis[i]; }
  static constexpr double length(int i) { return arm6::L[i]; }
};

// The outward pass through joints 1 .. 5, then joint 6's axis and link, which need no q6
// (b6 x = b5 x): body(I, k_I, r_I) for I = 0 .. 5 with r_I = L_I b_I x, joint 1 in closed form.
template <class Body>
inline void without_q6(const arm6::input& in, Body body) {
  using arm6::L;
  const trig<5> t(in.q);
  axes R = about_z(t.c[0], t.s[0]);
  body(std::integral_constant<int, 0>{}, v3{0, 0, 1}, v3{L[0] * t.c[0], L[0] * t.s[0], 0});
  joints<1, 5>([&](auto I) {
    const v3 k = R.e[axis[I]];
    turn<axis[I]>(R, t.c[I], t.s[I]);
    body(I, k, L[I] * R.e[0]);
  });
  body(std::integral_constant<int, 5>{}, R.e[0], L[5] * R.e[0]);
}
}  // namespace

namespace arm6 {
// Q1: R turned joint by joint (joint 1 in closed form, then two columns per joint), p summed
// from each body's first axis; sin and cos of all six joints.
void hand_q1(const input& in, output& out) {
  const trig<6> t(in.q);
  axes R = about_z(t.c[0], t.s[0]);
  v3 p = {L[0] * t.c[0], L[0] * t.s[0], 0};
  joints<1, 6>([&](auto I) {
    turn<axis[I]>(R, t.c[I], t.s[I]);
    p += L[I] * R.e[0];
  });
  for (int j = 0; j < 3; ++j) store(R.e[j], out.R + 3 * j);
  store(p, out.p);
}

// Q2: w += q'_i k_i and v += w x r_i joint by joint, joint 1 in closed form; no q6.
void hand_q2(const input& in, output& out) {
  v3 w, v;
  without_q6(in, [&](auto I, const v3& k, const v3& r) {
    if constexpr (I == 0) {
      w = {0, 0, in.qd[0]};
      v = {-in.qd[0] * r.y, in.qd[0] * r.x, 0};
    } else {
      w += in.qd[I] * k;
      v += cross(w, r);
    }
  });
  store(w, out.w);
  store(v, out.v);
}

// Q3: the axes k_i and links r_i of the pass, then k_i x (r_i + ... + r_6) summed backwards;
// no q6, and the last column's v is 0 (k_6 is along r_6).
void hand_q3(const input& in, output& out) {
  v3 k[6], r[6];
  without_q6(in, [&](auto I, const v3& kI, const v3& rI) { k[I] = kI, r[I] = rI; });
  v3 d = r[5];
  store(k[5], out.J + 30);
  store({0, 0, 0}, out.J + 33);
  for (int i = 4; i >= 0; --i) {
    d += r[i];
    store(k[i], out.J + 6 * i);
    store(cross(k[i], d), out.J + 6 * i + 3);
  }
}

// Q4: alpha += q''_i k_i + q'_i w x k_i, w += q'_i k_i, a += alpha x r_i + w x (w x r_i), joint 1
// in closed form; no q6.
void hand_q4(const input& in, output& out) {
  v3 w, al, a;
  without_q6(in, [&](auto I, const v3& k, const v3& r) {
    const double qd = in.qd[I], qdd = in.qdd[I];
    if constexpr (I == 0) {
      w = {0, 0, qd};
      al = {0, 0, qdd};
      a = {-qdd * r.y - qd * qd * r.x, qdd * r.x - qd * qd * r.y, 0};
    } else {
      al += qdd * k + qd * cross(w, k);
      w += qd * k;
      a += cross(al, r) + cross(w, cross(w, r));
    }
  });
  store(al, out.alpha);
  store(a, out.a);
}

// ALL: one outward pass for every quantity (hand.hpp's outward_pass: R, p, w, v, alpha, a and the
// Jacobian share the rotations, the k_i, the r_i and w x r_i), joint 1 in closed form.
void hand_all(const input& in, output& out) { outward_pass<6, model>(in.q, in.qd, in.qdd, out); }
}  // namespace arm6
