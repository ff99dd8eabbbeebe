// A state holds every coordinate it is asked for. Each case is a misuse (#ifdef) and its fix (#else).
// case index: kane: this coordinate is beyond the state. declare the state with NQ >= I
// case path: kane: the frames involved use a generalized coordinate beyond the state.s size
// case input: kane: this input is beyond the state. declare the state with NR >= I
// case linearized_input: kane: an input of linearize is beyond the state. declare the state with NR
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

double inputs() {
#ifdef KANE_CASE_input
  kane::state<double, 3> s;
#else
  kane::state<double, 3, 3, 0, 1> s;
#endif
  s[kane::r<1>] = 1.5;
  return s.q[0];
}

struct P : kane::point<kane::origin<N>, 0.5 * kane::e<A, 1>> {};
using pendulum =
    kane::system<kane::particle<P, kane::literal(2.0)>, kane::torque<A, kane::r<1> * kane::e<A, 3>>>;
double linearized() {
  using state = kane::state<double, 3, 3, 0, 1>;
  using evaluator = kane::evaluator<state, kane::frames<A>, kane::level::acceleration, kane::qdot_speeds<3>>;
#ifdef KANE_CASE_linearized_input
  using in = kane::inputs<kane::r<2>>;
#else
  using in = kane::inputs<kane::r<1>>;
#endif
  return kane::linearize<pendulum, evaluator, in>(state{}).B(0, 0);
}
