// KANE_STD_TRIG: an evaluator's sines and cosines of its coordinates are std::sin and std::cos, number
// for number (without it they come from kane's vector kernel, an ulp or two away).
#include <cmath>
#include <cstdio>

#include "../examples/models/pendulum_absolute.hpp"

int main() {
  namespace m = models::pendulum_absolute;
  kane::evaluator<kane::state<double, 2>, kane::frames<m::A, m::B>> ev;
  int wrong = 0;
  for (int n = 0; n < 1000; ++n) {
    kane::state<double, 2> s;
    s.q = {0.37 * n - 150.0, 1.3 - 0.011 * n};
    ev.update(s);
    const double* a = ev.axes<m::A>().data();  // e_A1 = (cos q1, sin q1, 0) in N
    const double* b = ev.axes<m::B>().data();
    wrong += !(a[0] == std::cos(s.q[0]) && a[1] == std::sin(s.q[0]) && b[0] == std::cos(s.q[1]) &&
               b[1] == std::sin(s.q[1]));
  }
  std::printf("%d of 1000 states differ from std::sin and std::cos\n", wrong);
  return wrong == 0 ? 0 : 1;
}
