// Generalized speeds, partial velocities and constraints keep their counts. Each case is a misuse
// (#ifdef) and its fix (#else).
// case partial_wrt_coordinate: partial_velocities_are_taken_with_respect_to_generalized_speeds_u_r<kane::coordinate<1(, 0)?(UL)?> ?>
// case partial_beyond_speeds: kane: u_R is not a generalized speed of this system
// case constraint_count: kane: m dependent speeds need m constraint equations
// case dependent_not_a_speed: kane: the dependent speeds must be speeds of the system
// case dependent_twice: kane: a dependent speed is named twice
// case speed_count: kane: a speed set defines as many speeds as the state has coordinates
// case too_many_holonomic: kane: more holonomic constraints than coordinates
// case configuration_not_scalar: kane: configuration constraints are scalar expressions
// case constraints_other_speeds: evaluator_and_constraints_use_different_speed_sets<kane::speeds<.*>, kane::qdot_speeds<2(UL)?> ?>
// case speeds_miss_a_rate: kane: these speeds do not determine q'
// case dependent_not_in_constraints: kane: the constraints do not determine the dependent speeds
// case solution_of_other_constraints: constraint_solution_of_other_constraints_solve_these<kane::nonholonomic<.*>, kane::nonholonomic<
// case remainder_other_speeds: evaluator_and_constraints_use_different_speed_sets<kane::qdot_speeds<2(UL)?>, kane::speeds<
// case partial_other_speeds: partial_velocity_of_another_speed_set_build_it_for_the_evaluators<kane::qdot_speeds<2(UL)?>, kane::speeds<
// case u_without_speed_set: evaluator_without_speed_set_reads_no_u_declare_the_speed_set<kane::speed<1(UL)?, 0(UL)?> ?>
// case rate_below_level: kane: q' and q'' are solved from the speeds at the velocity and acceleration levels
// case speed_not_linear: kane: a generalized speed is linear in q'
// case velocity_remainder_other_speeds: partial_velocity_of_another_speed_set_build_it_for_the_evaluators<kane::speeds<.*>, kane::speeds<
#include <kane/kane.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, q2>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, kane::e<B, 2>> {};

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
#else
  (void)kane::partial_velocity<sp>(w, kane::u<1>);
#endif
#ifdef KANE_CASE_partial_beyond_speeds
  (void)kane::partial_velocity<sp>(w, kane::u<3>);
#else
  (void)kane::partial_velocity<sp>(w, kane::u<2>);
#endif
#ifdef KANE_CASE_constraint_count
  (void)kane::nonholonomic<sp, kane::dependent<2>, c1, c1>::p;
#else
  (void)kane::nonholonomic<sp, kane::dependent<2>, c1>::p;
#endif
#ifdef KANE_CASE_dependent_not_a_speed
  (void)kane::nonholonomic<sp, kane::dependent<3>, c1>::p;
#else
  (void)kane::nonholonomic<sp, kane::dependent<1>, c1>::p;
#endif
#ifdef KANE_CASE_dependent_twice
  (void)kane::nonholonomic<kane::qdot_speeds<3>, kane::dependent<2, 2>, c1, c1>::p;
#else
  (void)kane::nonholonomic<kane::qdot_speeds<3>, kane::dependent<2, 3>, c1, c1>::p;
#endif
#ifdef KANE_CASE_speed_count
  kane::evaluator<kane::state<double, 3>, kane::frames<B>, kane::level::velocity, sp> ev3;
  (void)ev3;
#else
  kane::evaluator<kane::state<double, 2>, kane::frames<B>, kane::level::velocity, sp> ev3;
  (void)ev3;
#endif
#ifdef KANE_CASE_too_many_holonomic
  (void)kane::configuration<0, 0, kane::q<1>>::n;
#else
  (void)kane::configuration<1, 0, kane::q<1>>::n;
#endif
#ifdef KANE_CASE_configuration_not_scalar
  (void)kane::configuration<1, 0, kane::e<N, 1>>::n;
#else
  (void)kane::configuration<1, 0, kane::q<1>>::n;
#endif
#ifdef KANE_CASE_constraints_other_speeds
  using nh2 = kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<2>, c1>;
  x += kane::solve_constraints<nh2>(ev).A(0, 0);
#else
  using nh2 = kane::nonholonomic<sp, kane::dependent<2>, c1>;
  x += kane::solve_constraints<nh2>(ev).A(0, 0);
#endif
  // q1' in both speeds and q2' in none: Y is singular at every state; the fix is a speed with q2'
#ifdef KANE_CASE_speeds_miss_a_rate
  using bad = kane::speeds<kane::dt(kane::q<1>), 2.0 * kane::dt(kane::q<1>)>;
#else
  using bad = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>)>;
#endif
  kane::evaluator<St, kane::frames<B>, kane::level::velocity, bad> evb;
  evb.update(s);
  // c1 = ^N w^B . n3 = q1' does not involve u2, so u2 cannot be its dependent speed; u1 can
#ifdef KANE_CASE_dependent_not_in_constraints
  using nh3 = kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<2>, c1>;
#else
  using nh3 = kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<1>, c1>;
#endif
  kane::evaluator<St, kane::frames<B>, kane::level::velocity, kane::qdot_speeds<2>> evq;
  evq.update(s);
  x += kane::solve_constraints<nh3>(evq).A(0, 0) + evb.coordinate_value<1, 1>();
  // tables of nh take its own solution and an evaluator of its speed set
#ifdef KANE_CASE_solution_of_other_constraints
  const auto sol = kane::solve_constraints<kane::nonholonomic<sp, kane::dependent<2>, 2.0 * c1>>(ev);
#else
  const auto sol = kane::solve_constraints<nh>(ev);
#endif
  x += kane::nonholonomic_partial_velocities<N, nh>(w, ev, sol)(0, 0);
#ifdef KANE_CASE_remainder_other_speeds
  x += kane::nonholonomic_remainder<N, nh>(w, evq, sol)(0);
#else
  x += kane::nonholonomic_remainder<N, nh>(w, ev, sol)(0);
#endif
  // a symbolic partial velocity of sp reads sp's W = dq'/du: an evaluator of sp, not of q'
  constexpr auto v1 = kane::partial_velocity<sp>(kane::velocity<N, P>(), kane::u<2>);
#ifdef KANE_CASE_partial_other_speeds
  x += kane::express<N>(v1, evq)[0];
#else
  x += kane::express<N>(v1, ev)[0];
#endif
  // without a speed set u = q' and s.u is not read: reading u does not compile
  kane::evaluator<St, kane::frames<B>> ev0;
  ev0.update(s);
#ifdef KANE_CASE_u_without_speed_set
  x += kane::evaluate(kane::u<1>, ev0);
#else
  x += kane::evaluate(kane::u<1>, ev) + kane::evaluate(kane::dt(kane::q<1>), ev0);
#endif
  // q' of a speed set at the pose level is not solved; the fix is level::velocity
#ifdef KANE_CASE_rate_below_level
  kane::evaluator<St, kane::frames<B>, kane::level::pose, sp> evp;
#else
  kane::evaluator<St, kane::frames<B>, kane::level::velocity, sp> evp;
#endif
  evp.update(s);
  x += kane::evaluate(kane::dt(kane::q<1>), evp);
  // the remainder of sp (zero here, as for any speeds without Z) is read only by an evaluator of sp
  using sp2 = kane::speeds<kane::dot(w, kane::e<B, 1>), kane::dot(w, kane::e<B, 2>)>;
  kane::evaluator<St, kane::frames<B>, kane::level::velocity, sp2> ev2;
  ev2.update(s);
#ifdef KANE_CASE_velocity_remainder_other_speeds
  x += kane::express<B>(kane::velocity_remainder<sp>(w), ev2)[0];
#else
  x += kane::express<B>(kane::velocity_remainder<sp>(w), ev)[0] + kane::express<B>(w, ev2)[0];
#endif
  // a speed is linear in q': a product of rates is no speed; the fix is the rate itself
#ifdef KANE_CASE_speed_not_linear
  using squared = kane::speeds<kane::dt(kane::q<1>) * kane::dt(kane::q<1>), kane::dt(kane::q<2>)>;
#else
  using squared = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>)>;
#endif
  kane::evaluator<St, kane::frames<B>, kane::level::velocity, squared> evs;
  evs.update(s);
  x += evs.coordinate_value<1, 1>();
  return x;
}
