// The rolling disc (models/disc.hpp): the partial velocities of the centre
// with three coordinates, A and the nonholonomic partial velocities with five.
#include <cstdio>

#include "models/disc.hpp"

using namespace models::disc;

template <class M>
void print(const char* title, const M& m) {
  std::printf("%s\n", title);
  for (int i = 0; i < m.rows(); ++i) {
    std::printf("   ");
    for (int j = 0; j < m.cols(); ++j) std::printf(" % .6f", m(i, j));
    std::printf("\n");
  }
}

int main() {
  kane::state<double, 3, 3, 1> s3;
  s3.q = {0.3, 0.2, 1.0};
  s3.u = {0.5, -1.5, 0.8};
  s3.p = {0.25};
  // what the partial velocities of v_centre and w read: their frames at the pose level
  kane::evaluator_for<decltype(s3), kane::reads<kane::partials_of(v_centre), kane::partials_of(w)>, speeds3>
      ev3;
  ev3.update(s3);
  const auto V3 = kane::partial_velocities<N>(v_centre, ev3);  // v_r of the centre, in N
  print("partial velocities of the centre (columns v_1 v_2 v_3, in N):", V3);
  print("partial angular velocities of the disc (w_1 w_2 w_3, in N):", kane::partial_velocities<N>(w, ev3));

  kane::state<double, 5, 5, 1> s5;
  s5.q = {0.3, 0.2, 1.0, 2.0, -1.0};
  s5.u = {0.5, -1.5, 0.8, 0.0, 0.0};
  s5.p = {0.25};
  constexpr auto v5 = kane::velocity<N, Centre5>();  // the centre; v_below: the constraints
  // the constraints read the evaluator's pose: kane::evaluator of the frames the partials read
  using partials5 = kane::reads<kane::partials_of(v5), kane::partials_of(v_below)>;
  kane::evaluator_for<decltype(s5), partials5, speeds5>::evaluator_type ev5;
  ev5.update(s5);
  const auto sol = kane::solve_constraints<rolling>(ev5);  // u4, u5 = A (u1 u2 u3) + B
  if (sol.status != kane::solve_status::ok) return 1;
  print("A (rows u4 u5, columns u1 u2 u3):", sol.A);
  const auto V5 = kane::nonholonomic_partial_velocities<N, rolling>(v5, ev5, sol);
  print("nonholonomic partial velocities of the centre, five coordinates (in N):", V5);
  const double gap = (V5 - V3).cwiseAbs().maxCoeff();
  std::printf("largest difference to the three-coordinate disc: %.1e\n", gap);
  return gap < 1e-12 ? 0 : 1;
}
