#include <cmath>

#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};

int main() {
  kane::state<double, 1> s;
  s[kane::q<1>] = std::acos(-1.0) / 2;  // a quarter turn: n1 = -a2
  const kane::vec<A> n1 = kane::express<A>(kane::vec<N>::e1(), s);
  return kane::is_approx(n1, kane::vec<A>(0, -1, 0), 1e-15) ? 0 : 1;
}
