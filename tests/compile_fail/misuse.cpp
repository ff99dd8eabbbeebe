// The remaining rules of the types: numbering, scalar types, sizes, kinds of arguments. Each case
// is a misuse (#ifdef) and its fix (#else): the file as it is compiles every fix.
// case zero_denominator: kane: a constant.s denominator must not be zero
// case division_by_zero: kane: division by the constant zero
// case coordinate_zero: kane: generalized coordinates are numbered from 1
// case speed_zero: kane: generalized speeds are numbered from 1
// case parameter_zero: kane: parameters are numbered from 1
// case unit_index: kane: unit vectors are e<F, 1>, e<F, 2>, e<F, 3>
// case vec_scalar: kane: vec<F, S> needs a scalar type S
// case dcm_scalar: kane: dcm<A, B, S> needs a scalar type S
// case dcm_frames: kane: dcm<A, B> needs two frames
// case state_scalar: kane: state<S, NQ, ...> needs a scalar type S
// case frame_orientation: kane: frame<Parent, Orientation> needs an orientation
// case point_from: kane: point<From, r> needs a point From
// case point_vector: kane: point<From, r> needs a vector expression r
// case speeds_scalar: kane: speeds<u1, ..., un> takes scalar expressions
// case speed_beyond_state: kane: this speed is beyond the state
// case parameter_beyond_state: kane: this parameter is beyond the state
// case second_derivative_of_speed: kane: a state holds u and u' only
// case not_a_speed_set: kane: the fourth argument of evaluator is a speed set
// case fewer_speeds: kane: the state holds fewer speeds than the speed set defines
// case all_dependent: kane: at least one speed must stay independent
// case normalized_zero: kane: normalized.v. of the zero vector has no direction
// case acceleration_not_linear: kane: an angular acceleration is not linear in the speeds
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct O : kane::origin<N> {};
struct P : kane::point<O, kane::q<1> * kane::e<A, 1>> {};
using St = kane::state<double, 2, 2, 1>;

double use() {
  St s;
  s[kane::u<2>] = 1.0;
  s[kane::dt(kane::u<1>)] = 2.0;
  s[kane::parameter<1>{}] = 0.5;
  kane::evaluator<St, kane::frames<A>, kane::level::velocity, kane::qdot_speeds<2>> ev;
  ev.update(s);
  double x = kane::evaluate(kane::constant<1, 2>{} * kane::q<1> / kane::q<2>, ev);
  x += kane::express<N>(kane::velocity_remainder<kane::qdot_speeds<2>>(kane::velocity<N, P>()), ev)[0];
  using nh = kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<2>, kane::u<1> - kane::u<2>>;
  x += kane::solve_constraints<nh>(ev).A(0, 0);
  x += kane::dcm<N, A, float>()(0, 0) + kane::vec<N, float>()[0];
  // e1 - e1 is the zero vector as a type
#ifdef KANE_CASE_normalized_zero
  (void)kane::normalized(kane::e<A, 1> - kane::e<A, 1>);
#else
  (void)kane::normalized(kane::e<A, 1> - kane::e<A, 2>);
#endif
#ifdef KANE_CASE_zero_denominator
  (void)kane::constant<1, 0>{};
#else
  (void)kane::constant<1, 2>{};
#endif
#ifdef KANE_CASE_division_by_zero
  (void)(kane::q<1> / kane::zero_t{});
#else
  (void)(kane::q<1> / kane::q<2>);
#endif
#ifdef KANE_CASE_coordinate_zero
  (void)kane::coordinate<0>{};
#else
  (void)kane::coordinate<1>{};
#endif
#ifdef KANE_CASE_speed_zero
  (void)kane::speed<0>{};
#else
  (void)kane::speed<1>{};
#endif
#ifdef KANE_CASE_parameter_zero
  (void)kane::parameter<0>{};
#else
  (void)kane::parameter<1>{};
#endif
#ifdef KANE_CASE_unit_index
  (void)kane::unit<N, 4>{};
#else
  (void)kane::unit<N, 3>{};
#endif
#ifdef KANE_CASE_vec_scalar
  (void)kane::vec<N, int>{};
#else
  (void)kane::vec<N, float>{};
#endif
#ifdef KANE_CASE_dcm_scalar
  (void)kane::dcm<N, A, int>{};
#else
  (void)kane::dcm<N, A, float>{};
#endif
#ifdef KANE_CASE_dcm_frames
  (void)kane::dcm<N, int>{};
#else
  (void)kane::dcm<N, A>{};
#endif
#ifdef KANE_CASE_state_scalar
  (void)kane::state<int, 2>{};
#else
  (void)kane::state<float, 2>{};
#endif
#ifdef KANE_CASE_frame_orientation
  struct X1 : kane::frame<N, int> {};
  (void)X1{};
#else
  struct X1 : kane::frame<N, kane::simple<kane::axis::x, kane::coordinate<2>>> {};
  (void)X1{};
#endif
#ifdef KANE_CASE_point_from
  struct X2 : kane::point<int, kane::e<N, 1>> {};
  (void)X2{};
#else
  struct X2 : kane::point<O, kane::e<N, 1>> {};
  (void)X2{};
#endif
#ifdef KANE_CASE_point_vector
  struct X3 : kane::point<O, kane::q<1>> {};
  (void)X3{};
#else
  struct X3 : kane::point<O, kane::q<1> * kane::e<N, 1>> {};
  (void)X3{};
#endif
#ifdef KANE_CASE_speeds_scalar
  (void)kane::speeds<kane::e<N, 1>>::n;
#else
  (void)kane::speeds<kane::q<1>>::n;
#endif
#ifdef KANE_CASE_speed_beyond_state
  s[kane::u<3>] = 1.0;
#else
  s[kane::u<2>] = 1.0;
#endif
#ifdef KANE_CASE_parameter_beyond_state
  s[kane::parameter<2>{}] = 1.0;
#else
  s[kane::parameter<1>{}] = 1.0;
#endif
#ifdef KANE_CASE_second_derivative_of_speed
  s[kane::dt(kane::dt(kane::u<1>))] = 1.0;
#else
  s[kane::dt(kane::u<1>)] = 1.0;
#endif
#ifdef KANE_CASE_not_a_speed_set
  kane::evaluator<St, kane::frames<A>, kane::level::velocity, int> e2;
  (void)e2;
#else
  kane::evaluator<St, kane::frames<A>, kane::level::velocity, kane::qdot_speeds<2>> e2;
  (void)e2;
#endif
#ifdef KANE_CASE_fewer_speeds
  kane::evaluator<kane::state<double, 2, 1>, kane::frames<A>, kane::level::velocity, kane::qdot_speeds<2>> e3;
  (void)e3;
#else
  kane::evaluator<kane::state<double, 2, 2>, kane::frames<A>, kane::level::velocity, kane::qdot_speeds<2>> e3;
  (void)e3;
#endif
#ifdef KANE_CASE_all_dependent
  (void)kane::nonholonomic<kane::qdot_speeds<1>, kane::dependent<1>, kane::u<1>>::p;
#else
  (void)kane::nonholonomic<kane::qdot_speeds<2>, kane::dependent<1>, kane::u<1>>::p;
#endif
#ifdef KANE_CASE_acceleration_not_linear
  (void)kane::velocity_remainder<kane::qdot_speeds<2>>(kane::angular_acceleration<N, A>());
#else
  (void)kane::velocity_remainder<kane::qdot_speeds<2>>(kane::angular_velocity<N, A>());
#endif
  return x;
}
