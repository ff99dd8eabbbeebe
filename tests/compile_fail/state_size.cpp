// A state holds every coordinate it is asked for. Each case is a misuse (#ifdef) and its fix (#else).
// case index: kane: this coordinate is beyond the state. declare the state with NQ >= I
// case path: kane: the frames involved use a generalized coordinate beyond the state.s size
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<3>>> {};

double use() {
  kane::state<double, 3> s3;
  kane::state<double, 2> s2;
  s3[kane::q<3>] = 0.5;
#ifdef KANE_CASE_index
  s2[kane::q<3>] = 0.5;
#else
  s3[kane::q<3>] = 0.5;
#endif
#ifdef KANE_CASE_path
  return kane::direction_cosines<N, A>(s2)(0, 0);
#else
  return kane::direction_cosines<N, A>(s3)(0, 0) + s2.q[0];
#endif
}
