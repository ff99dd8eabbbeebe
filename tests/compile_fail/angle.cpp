// Angles of simple rotations: coordinates, parameters, numbers and t, all within the state; no speed.
// Each case is a misuse (#ifdef) and its fix (#else).
// case angle_speed: kane: simple<Axis, Angle> turns by a coordinate q_i, a parameter, a constant or
// case angle_coordinate: kane: a rotation angle uses a coordinate beyond the state
// case angle_parameter: kane: a rotation angle uses a parameter beyond the state
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct lam : kane::parameter<2> {};
#ifdef KANE_CASE_angle_speed
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::angle<kane::q<1> + kane::u<1>>>> {};
#else
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::angle<kane::q<1> + kane::q<2>>>> {};
#endif
struct B : kane::frame<A, kane::simple<kane::axis::x, kane::angle<kane::literal(2.0) * kane::q<1>>>> {};
struct C : kane::frame<B, kane::simple<kane::axis::y, lam>> {};

double use() {
#ifdef KANE_CASE_angle_coordinate
  kane::state<double, 1, 1, 2> s1;
#else
  kane::state<double, 2, 2, 2> s1;
#endif
  s1.p = {0.1, 0.2};
#ifdef KANE_CASE_angle_parameter
  kane::state<double, 2, 2, 1> s2;
#else
  kane::state<double, 2, 2, 2> s2;
#endif
  return kane::direction_cosines<N, A>(s1)(0, 0) + kane::direction_cosines<B, C>(s2)(0, 0);
}
