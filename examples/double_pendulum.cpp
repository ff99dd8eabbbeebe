// A planar double pendulum: A turns about n3 by q1, B about a3 by q2;
// P1 = O + L1 a1, P2 = P1 + L2 b1. Velocities and accelerations in N, checked
// against the closed form x = L1 cos q1 + L2 cos(q1 + q2), y = L1 sin q1 + L2 sin(q1 + q2).
#include <cmath>
#include <cstdio>

#include <kane/kane.hpp>
#include <kane/print.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
struct L1 : kane::parameter<1> {};
struct L2 : kane::parameter<2> {};

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::z, q2>> {};

struct O : kane::origin<N> {};
struct P1 : kane::point<O, L1{} * kane::e<A, 1>> {};
struct P2 : kane::point<P1, L2{} * kane::e<B, 1>> {};

int main() {
  kane::state<double, 2, 2, 2> s;
  s.q = {0.4, 1.1};
  s.qd = {0.9, -0.6};
  s.qdd = {-0.2, 0.5};
  s.p = {1.2, 0.7};

  constexpr auto v2 = kane::velocity<N, P2>();  // ^N v^P2, derived at compile time
  constexpr auto a2 = kane::acceleration<N, P2>();
  kane::evaluator_for<decltype(s), kane::reads<v2, a2>> ev;  // holds the values of v2 and a2
  ev.update(s);

  std::printf("^N v^P2 = %s\n", kane::to_string(v2).c_str());
  const kane::vec<N> vN = kane::express<N>(v2, ev);
  const kane::vec<N> aN = kane::express<N>(a2, ev);
  const kane::vec<B> vB = kane::express<B>(vN, s);  // the held value turned into B
  std::printf("^N v^P2 in N: (% .6f, % .6f, % .6f)\n", vN[0], vN[1], vN[2]);
  std::printf("^N v^P2 in B: (% .6f, % .6f, % .6f)\n", vB[0], vB[1], vB[2]);
  std::printf("^N a^P2 in N: (% .6f, % .6f, % .6f)\n", aN[0], aN[1], aN[2]);

  const double l1 = s.p[0], l2 = s.p[1], c1 = std::cos(s.q[0]), s1 = std::sin(s.q[0]);
  const double c12 = std::cos(s.q[0] + s.q[1]), s12 = std::sin(s.q[0] + s.q[1]);
  const double w1 = s.qd[0], w = s.qd[0] + s.qd[1], w1d = s.qdd[0], wd = s.qdd[0] + s.qdd[1];
  const kane::vec<N> v_closed(-l1 * s1 * w1 - l2 * s12 * w, l1 * c1 * w1 + l2 * c12 * w, 0);
  const kane::vec<N> a_closed(-l1 * (c1 * w1 * w1 + s1 * w1d) - l2 * (c12 * w * w + s12 * wd),
                              l1 * (-s1 * w1 * w1 + c1 * w1d) + l2 * (-s12 * w * w + c12 * wd), 0);
  const bool ok = kane::is_approx(vN, v_closed, 1e-12) && kane::is_approx(aN, a_closed, 1e-12);
  std::printf("closed form: %s\n", ok ? "agrees" : "DISAGREES");
  return ok ? 0 : 1;
}
