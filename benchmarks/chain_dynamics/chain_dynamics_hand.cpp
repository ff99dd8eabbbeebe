// Hand-written: Featherstone's articulated-body algorithm (O(n)) for the n-link
// chain of chain_dynamics.hpp, in body coordinates, plain doubles. Spatial
// vectors (angular; linear) at the body's joint. Joint i turns about a
// coordinate axis K of both bodies and sits l along the parent's x axis: every
// transform is a plane rotation (K a compile-time constant) and a shift along x.
// The unroll pragmas: g++ -O2 leaves the loops over 3 rolled (1.3x the instructions).
#include <cmath>
#include <type_traits>

#include "chain_dynamics.hpp"

#define HAND_INLINE [[gnu::always_inline]] inline

namespace {
using namespace chain_dynamics;

struct v3 {
  double x[3];
  double& operator[](int i) { return x[i]; }
  double operator[](int i) const { return x[i]; }
};
// a symmetric 3 x 3 matrix: xx, yy, zz, xy, yz, zx
constexpr int sym_index[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
struct sym {
  double m[6];
  double& operator()(int r, int s) { return m[sym_index[r][s]]; }
  double operator()(int r, int s) const { return m[sym_index[r][s]]; }
};
struct mat {
  double m[3][3];
  double& operator()(int r, int s) { return m[r][s]; }
  double operator()(int r, int s) const { return m[r][s]; }
};
struct motion {  // (w; v)
  v3 w, v;
};
struct force {  // (n; f)
  v3 n, f;
};
struct inertia6 {  // [A B; B^T C]: n = A w + B v, f = B^T w + C v
  sym A;
  mat B;
  sym C;
};

template <class M>
HAND_INLINE v3 times(const M& a, const v3& x) {
  v3 r;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) r[i] = a(i, 0) * x[0] + a(i, 1) * x[1] + a(i, 2) * x[2];
  return r;
}
HAND_INLINE v3 times_transposed(const mat& a, const v3& x) {
  v3 r;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) r[i] = a(0, i) * x[0] + a(1, i) * x[1] + a(2, i) * x[2];
  return r;
}
HAND_INLINE v3 cross(const v3& a, const v3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

struct link {   // per-link constants
  int k;        // joint axis
  double l;     // the joint's offset from the parent's joint along the parent's x
  sym A;        // rotational inertia about the joint, in the body's frame
  double m, h;  // mass, its offset along x
};
constexpr std::array<link, max_n> make_links() {
  std::array<link, max_n> t{};
  for (std::size_t i = 0; i < max_n; ++i) {
    const auto& j = inertia[i];
    const double m = mass[i], h = L[i] / 2;
    t[i] = {2 - int(i % 3),
            i == 0 ? 0 : L[i - 1],
            {{j[0], j[1] + m * h * h, j[2] + m * h * h, j[3], j[4], j[5]}},
            m,
            h};
  }
  return t;
}
constexpr std::array<link, max_n> links = make_links();

// The plane of the axis K: axes a, b (cyclic)
template <int K>
constexpr int a_of = (K + 1) % 3;
template <int K>
constexpr int b_of = (K + 2) % 3;
struct turn {  // cos, sin of q and their products
  double c, s, cc, ss, cs;
};
// x in the child's coordinates from the parent's, R^T x (R: by q about K); R x
template <int K>
HAND_INLINE void to_child(v3& x, const turn& t) {
  const double xa = x[a_of<K>], xb = x[b_of<K>];
  x[a_of<K>] = t.c * xa + t.s * xb, x[b_of<K>] = t.c * xb - t.s * xa;
}
template <int K>
HAND_INLINE void to_parent(v3& x, const turn& t) {
  const double xa = x[a_of<K>], xb = x[b_of<K>];
  x[a_of<K>] = t.c * xa - t.s * xb, x[b_of<K>] = t.s * xa + t.c * xb;
}
// R M R^T
template <int K>
HAND_INLINE void to_parent(sym& M, const turn& t) {
  constexpr int a = a_of<K>, b = b_of<K>;
  const double p = M(a, a), q = M(a, b), r = M(b, b), ak = M(a, K), bk = M(b, K);
  M(a, a) = t.cc * p - 2 * t.cs * q + t.ss * r;
  M(b, b) = t.ss * p + 2 * t.cs * q + t.cc * r;
  M(a, b) = t.cs * (p - r) + (t.cc - t.ss) * q;
  M(a, K) = t.c * ak - t.s * bk, M(b, K) = t.s * ak + t.c * bk;
}
template <int K>
HAND_INLINE void to_parent(mat& M, const turn& t) {
  constexpr int a = a_of<K>, b = b_of<K>;
#pragma GCC unroll 9
  for (int j = 0; j < 3; ++j) {
    const double ma = M(a, j), mb = M(b, j);
    M(a, j) = t.c * ma - t.s * mb, M(b, j) = t.s * ma + t.c * mb;
  }
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) {
    const double ma = M(i, a), mb = M(i, b);
    M(i, a) = t.c * ma - t.s * mb, M(i, b) = t.s * ma + t.c * mb;
  }
}
// a parent's motion in the child: shift to the joint (v - r x w, r = l e_x), rotate
template <int K>
HAND_INLINE motion to_child(const motion& p, double l, const turn& t) {
  motion m{p.w, {{p.v[0], p.v[1] + l * p.w[2], p.v[2] - l * p.w[1]}}};
  to_child<K>(m.w, t);
  to_child<K>(m.v, t);
  return m;
}
// f(std::integral_constant<int, k>)
template <class F>
HAND_INLINE void with_axis(int k, F&& f) {
  switch (k) {
    case 0:
      return f(std::integral_constant<int, 0>{});
    case 1:
      return f(std::integral_constant<int, 1>{});
    default:
      return f(std::integral_constant<int, 2>{});
  }
}

template <std::size_t N>
void aba(const input& in, output& out) {
  turn t[N];
  motion c[N];  // velocity-product accelerations
  force p[N];   // bias forces
  inertia6 I[N];
  // outward: velocities, c, and p of the rigid bodies
  motion vp{};
  for (std::size_t i = 0; i < N; ++i)
    with_axis(links[i].k, [&]<int K>(std::integral_constant<int, K>) {
      constexpr int a = a_of<K>, b = b_of<K>;
      const link& lk = links[i];
      const double cq = std::cos(in.q[i]), sq = std::sin(in.q[i]), qd = in.qd[i];
      t[i] = {cq, sq, cq * cq, sq * sq, cq * sq};
      motion v = to_child<K>(vp, lk.l, t[i]);
      v.w[K] += qd;
      c[i].w[K] = 0, c[i].w[a] = v.w[b] * qd, c[i].w[b] = -v.w[a] * qd;  // v x (e_K q')
      c[i].v[K] = 0, c[i].v[a] = v.v[b] * qd, c[i].v[b] = -v.v[a] * qd;
      // the body's momentum (n; f) = I v, B = m h e_x~, C = m 1; p = v x* I v
      const double mh = lk.m * lk.h;
      const v3 aw = times(lk.A, v.w);
      const v3 n{{aw[0], aw[1] - mh * v.v[2], aw[2] + mh * v.v[1]}};
      const v3 f{{lk.m * v.v[0], lk.m * v.v[1] + mh * v.w[2], lk.m * v.v[2] - mh * v.w[1]}};
      const v3 wn = cross(v.w, n), vf = cross(v.v, f);
      p[i].n = {{wn[0] + vf[0], wn[1] + vf[1], wn[2] + vf[2]}};
      p[i].f = cross(v.w, f);
      I[i] = {lk.A, {{{0, 0, 0}, {0, 0, -mh}, {0, mh, 0}}}, {{lk.m, lk.m, lk.m, 0, 0, 0}}};
      vp = v;
    });
  // inward: articulated inertias and bias forces; U = I^A e_K, D = U_K, u = -p_K
  v3 Un[N], Uf[N];
  double D[N], u[N];
  for (std::size_t i = N; i-- > 0;)
    with_axis(links[i].k, [&]<int K>(std::integral_constant<int, K>) {
      inertia6& Ia = I[i];
      v3 &un = Un[i], &uf = Uf[i];
#pragma GCC unroll 9
      for (int j = 0; j < 3; ++j) un[j] = Ia.A(j, K), uf[j] = Ia.B(K, j);
      D[i] = Ia.A(K, K);
      u[i] = -p[i].n[K];
      if (i == 0) return;
      // I^a = I^A - U U^T / D, p^a = p + I^a c + U u / D
      const double d = 1 / D[i], ud = u[i] * d;
#pragma GCC unroll 9
      for (int r = 0; r < 3; ++r)
#pragma GCC unroll 9
        for (int s = 0; s < 3; ++s) {
          if (s >= r) Ia.A(r, s) -= un[r] * un[s] * d, Ia.C(r, s) -= uf[r] * uf[s] * d;
          Ia.B(r, s) -= un[r] * uf[s] * d;
        }
      const v3 an = times(Ia.A, c[i].w), bn = times(Ia.B, c[i].v), bf = times_transposed(Ia.B, c[i].w),
               cf = times(Ia.C, c[i].v);
      force pa;
#pragma GCC unroll 9
      for (int j = 0; j < 3; ++j) {
        pa.n[j] = p[i].n[j] + an[j] + bn[j] + un[j] * ud;
        pa.f[j] = p[i].f[j] + bf[j] + cf[j] + uf[j] * ud;
      }
      // to the parent: rotate, then shift by r = l e_x
      const turn& tr = t[i];
      to_parent<K>(pa.n, tr);
      to_parent<K>(pa.f, tr);
      to_parent<K>(Ia.A, tr);
      to_parent<K>(Ia.B, tr);
      to_parent<K>(Ia.C, tr);
      const double l = links[i].l, l2 = l * l;
      force& pp = p[i - 1];
      pp.n[0] += pa.n[0], pp.n[1] += pa.n[1] - l * pa.f[2], pp.n[2] += pa.n[2] + l * pa.f[1];  // + r x f
      pp.f[0] += pa.f[0], pp.f[1] += pa.f[1], pp.f[2] += pa.f[2];
      // [A + l (P + P^T) - l^2 X C X, B + l X C; ., C], X = e_x~, P = X B^T
      const sym &A = Ia.A, &C = Ia.C;
      const mat& B = Ia.B;
      inertia6& Q = I[i - 1];
      Q.A(0, 0) += A(0, 0);
      Q.A(1, 1) += A(1, 1) - 2 * l * B(1, 2) + l2 * C(2, 2);
      Q.A(2, 2) += A(2, 2) + 2 * l * B(2, 1) + l2 * C(1, 1);
      Q.A(0, 1) += A(0, 1) - l * B(0, 2);
      Q.A(1, 2) += A(1, 2) + l * (B(1, 1) - B(2, 2)) - l2 * C(1, 2);
      Q.A(2, 0) += A(2, 0) + l * B(0, 1);
#pragma GCC unroll 9
      for (int s = 0; s < 3; ++s) {
        Q.B(0, s) += B(0, s);
        Q.B(1, s) += B(1, s) - l * C(2, s);
        Q.B(2, s) += B(2, s) + l * C(1, s);
      }
#pragma GCC unroll 9
      for (int r = 0; r < 6; ++r) Q.C.m[r] += C.m[r];
    });
  // outward: accelerations and q''
  motion ap{{{0, 0, 0}}, {{0, 0, g}}};  // the base accelerates up: gravity
  for (std::size_t i = 0; i < N; ++i)
    with_axis(links[i].k, [&]<int K>(std::integral_constant<int, K>) {
      motion a = to_child<K>(ap, links[i].l, t[i]);
#pragma GCC unroll 9
      for (int j = 0; j < 3; ++j) a.w[j] += c[i].w[j], a.v[j] += c[i].v[j];
      const v3 &un = Un[i], &uf = Uf[i];
      const double ua =
          un[0] * a.w[0] + un[1] * a.w[1] + un[2] * a.w[2] + uf[0] * a.v[0] + uf[1] * a.v[1] + uf[2] * a.v[2];
      const double qdd = (u[i] - ua) / D[i];
      out.qdd[i] = qdd;
      a.w[K] += qdd;
      ap = a;
    });
}
}  // namespace

template <std::size_t N>
void chain_dynamics::hand_forward(const input& in, output& out) {
  aba<N>(in, out);
}
template void chain_dynamics::hand_forward<6>(const input&, output&);
template void chain_dynamics::hand_forward<12>(const input&, output&);
template void chain_dynamics::hand_forward<24>(const input&, output&);
template void chain_dynamics::hand_forward<48>(const input&, output&);
