// A small tree N -> A -> B -> C, its direction cosines, and one vector
// expressed in several frames.
#include <cstdio>

#include <kane/kane.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
using q3 = kane::coordinate<3>;

struct N : kane::root_frame {};                                 // Newtonian frame
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};  // about n3 by q1
struct B : kane::frame<A, kane::simple<kane::axis::x, q2>> {};  // about a1 by q2
struct C : kane::frame<B, kane::simple<kane::axis::y, q3>> {};  // about b2 by q3

template <class F>
void print(const char* name, const kane::vec<F>& p) {
  std::printf("^%s p = (% .6f, % .6f, % .6f)\n", name, p[0], p[1], p[2]);
}

int main() {
  kane::state<double, 3> s;
  s[kane::q<1>] = 0.5;
  s[kane::q<2>] = -0.3;
  s[kane::q<3>] = 1.2;

  const auto NPC = kane::direction_cosines<N, C>(s);  // ^N P^C
  std::printf("^N P^C =\n");
  for (int i = 0; i < 3; ++i) std::printf("  % .6f % .6f % .6f\n", NPC(i, 0), NPC(i, 1), NPC(i, 2));

  const kane::vec<C> pC(1.0, 2.0, 3.0);  // ^C p
  print("C", pC);
  print("B", kane::express<B>(pC, s));
  print("A", kane::express<A>(pC, s));
  const kane::vec<N> pN = kane::express<N>(pC, s);
  print("N", pN);
  print("C", NPC * pN);  // ^C p = ^N P^C . ^N p: back where it started
  std::printf("|p| = %.6f in N and %.6f in C\n", kane::norm(pN), kane::norm(pC));
  return kane::is_approx(NPC * pN, pC, 1e-12) ? 0 : 1;
}
