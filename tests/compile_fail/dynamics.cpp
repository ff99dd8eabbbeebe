// Systems of Kane's dynamical equations: an inertia in a frame fixed in its body, about
// its mass centre; forces at particles or at points fixed in bodies.
// Each case is a misuse (#ifdef) and its fix (#else).
// case inertia_in_turning_frame: inertia_given_in_a_frame_that_turns_relative_to_the_body<.*A, .*B>
// case inertia_about_other_point: inertia_about_another_point_than_the_mass_centre_use_parallel_axis<.*J, .*Bo>, .*give_the_inertia_about_the_mass_centre<.*Bo>
// case force_at_massless_point: force_at_a_point_of_no_mass_apply_it_at_a_particle_or_a_point_fixed_in_a_body<.*S>
// case wheel_inertia_not_symmetric: inertia_given_in_a_frame_that_turns_relative_to_the_body<.*B, .*W>
// case spinning_inertia_not_symmetric: inertia_in_a_spinning_frame_is_symmetric_about_its_spin_axis<.*W>
// case torque_from_other_tree: frames_of_two_trees_relate_them_through_a_common_root_frame<M, N>
// case equations_on_other_speeds: evaluator_and_constraints_use_different_speed_sets<kane::qdot_speeds<2>, kane::speeds<
// case particle_mass_not_scalar: kane: particle<P, m> takes a scalar expression m
// case inertia_not_inertia: kane: rigid_body<B, Bo, m, I> takes I = kane::inertia<F, Bo, ...>
// case wheel_speed_not_in_set: a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<.*W>
// case potential_of_velocity_point: potential_energy_needs_positions_from_an_origin_not_from_a_point_known_by_its_velocity<.*Bv>
// case spring_stiffness_not_scalar: kane: spring<P, Q, k, L> takes scalar expressions k .stiffness. and L
// case linear_index_not_in_x: kane: u_r is not a speed of this x
// case motion_wrong_size: kane: x and dx/dt of kane::motion hold nq \+ nu numbers
// case motion_index_beyond: kane: u_r is not a speed of this x .u_1 .. u_nu.
// case constrained_index_dependent: kane: u_r is not an independent speed of this x
// case motion_state_of_other_type: kane: motion takes the state of its evaluator. for kane::motion<System> declare it kane::state_of<System>
// case motion_second_argument: kane: the second argument is an evaluator .kane::evaluator<...>. or a speed set
// case cut_names_no_mass: kane: cut<P, Items...> names no body .by its frame. or particle .by its point. of the system
// case derivatives_of_world_load: analytical_derivatives_need_loads_fixed_in_their_bodies<kane::force<.*Bo
// case derivatives_without_joint_form: analytical_derivatives_need_a_tree_of_simple_rotations_with_u_equal_to_q_dot<
// case derivatives_of_reordered_rates: analytical_derivatives_need_a_tree_of_simple_rotations_with_u_equal_to_q_dot<
// case linearize_lanes_by_sums: kane: linearize over kane::lanes takes the analytical derivatives
// case linearize_lanes_by_parameter: kane: linearize over kane::lanes takes inputs of the state
// case linearize_constrained_lanes: kane: linearize_constrained takes one state at a time
// case linearize_equations_lanes: kane: linearize_equations takes one state at a time
// case cut_of_a_vector: kane: cut<P, Items...> takes the frames of the part's bodies and the points of its particles
// case eigenvalues_of_a_dynamic_matrix: kane: eigenvalues takes a square matrix of real numbers of fixed size
// A case's compile defines KANE_A_CASE: then it compiles only the functions its misuse reaches. The
// accepted twin compiles all. The types that several functions share (sys, steered, ...) keep their
// fixes: a misuse is a type or a call of its case alone, on the lines of its #ifdef or in a function
// compiled under KANE_A_CASE for that case alone. So the one compile of all cases gives each error to
// its case.
#include <array>

#include <kane/kane.hpp>
#include <kane/scalars/lanes.hpp>

template <std::size_t I>
using q = kane::coordinate<I>;
template <std::size_t I>
inline constexpr kane::parameter<I> p{};
using kane::e;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::x, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::y, q<2>>> {};
struct T : kane::frame<B, kane::simple<kane::axis::z, kane::constant<1, 3>>> {};  // fixed in B
struct O : kane::origin<N> {};
struct J : kane::point<O, -p<1> * e<A, 3>> {};
struct Bo : kane::point<J, -p<2> * e<B, 3>> {};
struct S : kane::point<O, p<2> * e<A, 1> + kane::q<2> * e<N, 2>> {};  // on no body
struct M : kane::root_frame {};                                       // another tree
using inertia = kane::inertia<T, Bo, p<4>, p<4>, p<5>>;
using body = kane::rigid_body<B, Bo, p<3>, inertia>;
using tip = kane::particle<J, p<6>>;
using push = kane::force<Bo, p<7> * e<N, 1>>;
using twist = kane::torque<B, p<9> * e<N, 1>>;
// The system with its body, particle, force and torque; sys_with<...> with some of them replaced.
template <class Body = body, class Tip = tip, class Push = push, class Twist = twist>
using sys_with = kane::system<Body, Tip, Push, Twist, kane::gravity<-p<8> * e<N, 3>>>;
using sys = sys_with<>;

// M(0, 0) of Kane's equations of System at the speeds q'.
template <class System>
double equations() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, kane::qdot_speeds<2>> ev;
  ev.update(s);
  return kane::mass_matrix_and_forcing<System>(ev).M(0, 0);
}
// Each misuse replaces one item of sys; each fix is sys itself.
#if !defined(KANE_A_CASE) || defined(KANE_CASE_inertia_in_turning_frame)
double inertia_in_turning_frame() {
#ifdef KANE_CASE_inertia_in_turning_frame
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, kane::inertia<A, Bo, p<4>, p<4>, p<5>>>>>();
#else
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, kane::inertia<T, Bo, p<4>, p<4>, p<5>>>>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_inertia_about_other_point)
double inertia_about_other_point() {
#ifdef KANE_CASE_inertia_about_other_point
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, kane::inertia<T, J, p<4>, p<4>, p<5>>>>>();
#else
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, kane::inertia<T, Bo, p<4>, p<4>, p<5>>>>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_inertia_not_inertia)
double inertia_not_inertia() {
#ifdef KANE_CASE_inertia_not_inertia
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, T>>>();
#else
  return equations<sys_with<kane::rigid_body<B, Bo, p<3>, inertia>>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_particle_mass_not_scalar)
double particle_mass_not_scalar() {
#ifdef KANE_CASE_particle_mass_not_scalar
  return equations<sys_with<body, kane::particle<J, e<N, 1>>>>();
#else
  return equations<sys_with<body, kane::particle<J, p<6>>>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_force_at_massless_point)
double force_at_massless_point() {
#ifdef KANE_CASE_force_at_massless_point
  return equations<sys_with<body, tip, kane::force<S, p<7> * e<N, 1>>>>();
#else
  return equations<sys_with<body, tip, kane::force<Bo, p<7> * e<N, 1>>>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_torque_from_other_tree)
double torque_from_other_tree() {
#ifdef KANE_CASE_torque_from_other_tree
  return equations<sys_with<body, tip, push, kane::torque<B, p<9> * e<M, 1>>>>();
#else
  return equations<sys_with<body, tip, push, kane::torque<B, p<9> * e<N, 1>>>>();
#endif
}
#endif

// a wheel spinning in B about b2: its inertia may be given in B if symmetric about b2
struct W : kane::frame<B, kane::spin<kane::axis::y, kane::speed<3>>> {};
using wheel = kane::rigid_body<W, Bo, p<3>, kane::inertia<B, Bo, p<4>, p<5>, p<4>>>;
#ifdef KANE_CASE_wheel_inertia_not_symmetric
static_assert(sizeof(kane::rigid_body<W, Bo, p<3>, kane::inertia<B, Bo, p<4>, p<5>, p<6>>>) > 0);
#else
static_assert(sizeof(wheel) > 0);
#endif
// given in the spinning frame itself, the inertia is symmetric about the spin axis too
#ifdef KANE_CASE_spinning_inertia_not_symmetric
static_assert(sizeof(kane::rigid_body<W, Bo, p<3>, kane::inertia<W, Bo, p<4>, p<5>, p<6>>>) > 0);
#else
static_assert(sizeof(kane::rigid_body<W, Bo, p<3>, kane::inertia<W, Bo, p<4>, p<5>, p<4>>>) > 0);
#endif
// the wheel's speed u3 is a free speed of the evaluator's speed set, though W is not among its frames
#if !defined(KANE_A_CASE) || defined(KANE_CASE_wheel_speed_not_in_set)
double use_wheel() {
#ifdef KANE_CASE_wheel_speed_not_in_set
  using wheel_speeds = kane::qdot_speeds<2>;
#else
  using wheel_speeds = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>), kane::free_speed>;
#endif
  kane::state<double, 2, 3, 9> s;
  kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, wheel_speeds> ev;
  ev.update(s);
  return kane::mass_matrix_and_forcing<kane::system<body, wheel>>(ev).M(0, 0);
}
#endif

// q2' = q1' as a nonholonomic constraint on the speeds u1 = q1', u2 = q2'
using rates = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>)>;
using tied = kane::nonholonomic<rates, kane::dependent<2>, kane::dt(kane::q<2>) - kane::dt(kane::q<1>)>;
#ifdef KANE_CASE_equations_on_other_speeds
using tied_speeds = kane::qdot_speeds<2>;
#else
using tied_speeds = rates;
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_equations_on_other_speeds)
double use_tied() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, tied_speeds> ev;
  ev.update(s);
  return kane::reduced_mass_matrix_and_forcing<sys, tied>(ev, kane::solve_constraints<tied>(ev))
      .reduced.M(0, 0);
}
#endif

#if !defined(KANE_A_CASE) || defined(KANE_CASE_cut_names_no_mass) || defined(KANE_CASE_cut_of_a_vector)
// The pin's reaction on the body fixed in B: a cut names bodies by their frames, particles by their points.
double pin() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, kane::qdot_speeds<2>> ev;
  ev.update(s);
  double x = 0;
#ifdef KANE_CASE_cut_names_no_mass
  x += kane::reaction<sys, kane::cut<J, A>>(ev).force[0];  // no body is fixed in A
#else
  x += kane::reaction<sys, kane::cut<J, B>>(ev).force[0];
#endif
#ifdef KANE_CASE_cut_of_a_vector
  x += kane::reaction<sys, kane::cut<J, decltype(e<B, 1>)>>(ev).force[0];
#else
  x += kane::reaction<sys, kane::cut<J, B>>(ev).force[0];
#endif
  return x;
}
#endif

#if !defined(KANE_A_CASE) || defined(KANE_CASE_motion_wrong_size) || defined(KANE_CASE_motion_index_beyond)
double integrate() {
  kane::state<double, 2, 2, 9> s;
  using ev_type =
      kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, kane::qdot_speeds<2>>;
  kane::motion<sys, ev_type> f(s);
#ifdef KANE_CASE_motion_wrong_size
  std::array<double, 3> x{}, dx{};
  f(x, dx, 0.0);
#else
  std::array<double, 4> x{}, dx{};
  f(x, dx, 0.0);
#endif
  // x's entries by name: u_3 is none of the two speeds'
#ifdef KANE_CASE_motion_index_beyond
  return dx[f.index(kane::u<3>)];
#else
  return dx[f.index(kane::u<2>)];
#endif
}
#endif

#if !defined(KANE_A_CASE) || defined(KANE_CASE_constrained_index_dependent)
double integrate_tied() {
  kane::state<double, 2, 2, 9> s;
  using ev_type = kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, rates>;
  kane::constrained_motion<sys, tied, ev_type> f(s);
  std::array<double, 3> x{}, dx{};
  f(x, dx, 0.0);
  // x = (q1, q2, u1): the dependent u_2 is not in it
#ifdef KANE_CASE_constrained_index_dependent
  return dx[f.index(kane::u<2>)];
#else
  return dx[f.index(kane::u<1>)];
#endif
}
#endif

// A body whose mass centre is known by its velocity: momentum and kinetic energy, no potential.
struct Bv : kane::point_by_velocity<N, kane::dt(kane::q<1>) * p<1> * e<A, 2>> {};
using rolling_sys = kane::system<kane::rigid_body<B, Bv, p<3>, kane::inertia<B, Bv, p<4>, p<4>, p<5>>>,
                                 kane::gravity<-p<8> * e<N, 3>>>;
#if !defined(KANE_A_CASE) || defined(KANE_CASE_potential_of_velocity_point)
double energy() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<B>, kane::level::velocity> ev;
  ev.update(s);
#ifdef KANE_CASE_potential_of_velocity_point
  return kane::potential_energy<rolling_sys>(ev);
#else
  return kane::kinetic_energy<rolling_sys>(ev) + kane::angular_momentum<rolling_sys>(ev)[0];
#endif
}
#endif

// A spring from O to a particle at Bo.
#ifdef KANE_CASE_spring_stiffness_not_scalar
using stretched = kane::system<kane::particle<Bo, p<3>>, kane::spring<O, Bo, p<6> * e<N, 1>, p<7>>>;
#else
using stretched = kane::system<kane::particle<Bo, p<3>>, kane::spring<O, Bo, p<6>, p<7>>>;
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_spring_stiffness_not_scalar)
double stretched_energy() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<B>, kane::level::acceleration> ev;
  ev.update(s);
  return kane::potential_energy<stretched>(ev) + kane::mass_matrix_and_forcing<stretched>(ev).f(0);
}
#endif

// Analytical derivatives: a tree of simple rotations by q, loads fixed in the bodies they act on.
using steered = kane::system<body, tip, kane::force<Bo, p<7> * e<B, 1>>, kane::gravity<-p<8> * e<N, 3>>>;
template <class System, class Speeds = kane::qdot_speeds<2>>
double derivative() {
  kane::state<double, 2, 2, 9> s;
  kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, Speeds> ev;
  ev.update(s);
  return kane::forward_dynamics_derivatives<System>(ev).dud_dq(0, 0);
}
#if !defined(KANE_A_CASE) || defined(KANE_CASE_derivatives_of_world_load)
double derivatives_of_world_load() {
#ifdef KANE_CASE_derivatives_of_world_load
  return derivative<kane::system<body, tip, push, kane::gravity<-p<8> * e<N, 3>>>>();  // push is along n1
#else
  return derivative<steered>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_derivatives_of_reordered_rates)
double derivatives_of_reordered_rates() {
#ifdef KANE_CASE_derivatives_of_reordered_rates
  // the recursive passes, u != q'
  return derivative<steered, kane::speeds<kane::dt(q<2>{}), kane::dt(q<1>{})>>();
#else
  return derivative<steered>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_derivatives_without_joint_form)
double derivatives_without_joint_form() {
#ifdef KANE_CASE_derivatives_without_joint_form
  return derivative<rolling_sys>();  // Bv is known by its velocity
#else
  return derivative<steered>();
#endif
}
#endif

#if !defined(KANE_A_CASE) || defined(KANE_CASE_linear_index_not_in_x)
// Rows and columns of a linearization by coordinate and speed.
double linear_entry() {
  kane::state<double, 2, 2, 9> s;
  using ev_type =
      kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, kane::qdot_speeds<2>>;
  const auto lin = kane::linearize<kane::system<kane::particle<Bo, p<3>>>, ev_type>(s);
  using L = std::remove_cvref_t<decltype(lin)>;
#ifdef KANE_CASE_linear_index_not_in_x
  return lin.A(L::index(kane::q<1>), L::index(kane::u<3>));
#else
  return lin.A(L::index(kane::q<1>), L::index(kane::u<2>));
#endif
}
#endif

// kane::motion<System>: its state is kane::state_of<System>; its second argument a speed set or an evaluator.
using pendulum = kane::system<kane::particle<Bo, p<3>>, kane::gravity<-p<8> * e<N, 3>>>;
#if !defined(KANE_A_CASE) || defined(KANE_CASE_motion_state_of_other_type)
double own_motion() {
#ifdef KANE_CASE_motion_state_of_other_type
  kane::state<double, 2, 2, 9> s;
#else
  kane::state_of<pendulum> s;
#endif
  kane::motion<pendulum, kane::qdot_speeds<2>> f(s);
  std::array<double, 4> x{}, dx{};
  f(x, dx, 0.0);
  return dx[3];
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_motion_second_argument)
double motion_at_speeds() {
  kane::state_of<pendulum> s;
#ifdef KANE_CASE_motion_second_argument
  kane::motion<pendulum, double> f(s);
#else
  kane::motion<pendulum, kane::qdot_speeds<2>> f(s);
#endif
  std::array<double, 4> x{}, dx{};
  f(x, dx, 0.0);
  return dx[3];
}
#endif

// Linearization over kane::lanes: the analytical derivatives with inputs of the state; one state at a
// time otherwise.
using two = kane::lanes<double, 2>;
template <class Speeds, class Inputs = kane::inputs<kane::r<1>>>
double lanes_linearization() {
  kane::state<two, 2, 2, 9, 1> s;
  using ev_type = kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, Speeds>;
  return kane::linearize<steered, ev_type, Inputs>(s).A(0, 0)[0];
}
#if !defined(KANE_A_CASE) || defined(KANE_CASE_linearize_lanes_by_sums)
double linearize_lanes_by_sums() {
#ifdef KANE_CASE_linearize_lanes_by_sums
  return lanes_linearization<kane::speeds<kane::dt(q<2>{}), kane::dt(q<1>{})>>();  // u != q': Kane's sums
#else
  return lanes_linearization<kane::qdot_speeds<2>>();
#endif
}
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_linearize_lanes_by_parameter)
double linearize_lanes_by_parameter() {
#ifdef KANE_CASE_linearize_lanes_by_parameter
  return lanes_linearization<kane::qdot_speeds<2>, kane::inputs<p<7>>>();
#else
  return lanes_linearization<kane::qdot_speeds<2>, kane::inputs<kane::r<1>>>();
#endif
}
#endif
#ifdef KANE_CASE_linearize_constrained_lanes
using tied_number = two;
#else
using tied_number = double;
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_linearize_constrained_lanes)
double tied_linearization() {
  kane::state<tied_number, 2, 2, 9> s;
  using ev_type = kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, rates>;
  return kane::linearize_constrained<sys, tied, ev_type>(s).status == kane::status_of<tied_number>{};
}
#endif
#ifdef KANE_CASE_linearize_equations_lanes
using reduced_number = two;
#else
using reduced_number = double;
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_linearize_equations_lanes)
double reduced_linearization() {
  kane::state<reduced_number, 2, 2, 9> s;
  using ev_type = kane::evaluator<decltype(s), kane::frames<T>, kane::level::acceleration, rates>;
  return kane::linearize_equations<sys, tied, ev_type>(s).status == kane::status_of<reduced_number>{};
}
#endif
#ifdef KANE_CASE_eigenvalues_of_a_dynamic_matrix
using stability_matrix = Eigen::MatrixXd;
#else
using stability_matrix = Eigen::Matrix2d;
#endif
#if !defined(KANE_A_CASE) || defined(KANE_CASE_eigenvalues_of_a_dynamic_matrix)
double stability() {
  const stability_matrix a = Eigen::Matrix2d::Identity();
  return kane::eigenvalues(a).values(0).real();
}
#endif
