// Generalized speeds, partial velocities and constraints keep their counts.
// case partial_wrt_coordinate: deleted && partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r && coordinate<1
// case partial_beyond_speeds: kane: u_R is not a generalized speed of this system
// case constraint_count: kane: m dependent speeds need m constraint equations
// case dependent_not_a_speed: kane: the dependent speeds must be speeds of the system
// case dependent_twice: kane: a dependent speed is named twice
// case speed_count: kane: a speed set defines as many speeds as the state has coordinates
// case too_many_holonomic: kane: more holonomic constraints than coordinates
// case constraints_other_speeds: kane: the constraints and the evaluator use different speed sets
#include <kane/kane.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, q2>> {};

inline constexpr auto w = kane::angular_velocity<N, B>();
using sp = kane::speeds<kane::dot(w, kane::e<B, 1>), kane::dot(w, kane::e<B, 3>)>;
using St = kane::state<double, 2>;
using Ev = kane::evaluator<St, kane::frames<B>, kane::level::velocity, sp>;
inline constexpr auto c1 = kane::dot(w, kane::e<N, 3>);

double use() {
  St s;
  Ev ev;
  ev.update(s);
  double x = kane::express<N>(kane::partial_velocity<sp>(w, kane::u<2>), ev)[0];
  using nh = kane::nonholonomic<sp, kane::dependent<2>, c1>;
  x += kane::solve_constraints<nh>(ev).A(0, 0);
  using cfg = kane::configuration<1, 0, kane::q<1> - kane::q<2>>;
  x += kane::residuals<cfg>(ev)[0];
#ifdef KANE_CASE_partial_wrt_coordinate
  (void)kane::partial_velocity<sp>(w, kane::q<1>);
#endif
#ifdef KANE_CASE_partial_beyond_speeds
  (void)kane::partial_velocity<sp>(w, kane::u<3>);
#endif
#ifdef KANE_CASE_constraint_count
  (void)kane::nonholonomic<sp, kane::dependent<2>, c1, c1>::p;
#endif
#ifdef KANE_CASE_dependent_not_a_speed
  (void)kane::nonholonomic<sp, kane::dependent<3>, c1>::p;
#endif
#ifdef KANE_CASE_dependent_twice
  (void)kane::nonholonomic<kane::qdot_speeds<3>, kane::dependent<2, 2>, c1, c1>::p;
#endif
#ifdef KANE_CASE_speed_count
  kane::evaluator<kane::state<double, 3>, kane::frames<B>, kane::level::velocity, sp> ev3;
  (void)ev3;
#endif
#ifdef KANE_CASE_too_many_holonomic
  (void)kane::configuration<0, 0, kane::q<1>>::n;
#endif
#ifdef KANE_CASE_constraints_other_speeds
  using nh2 = kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<2>, c1>;
  x += kane::solve_constraints<nh2>(ev).A(0, 0);
#endif
  return x;
}
