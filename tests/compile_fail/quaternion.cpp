// Euler parameters: four different coordinates; unit_norm of a frame they orient; held rows last.
// Each case is a misuse (#ifdef) and its fix (#else).
// case three_parameters: kane: euler_parameters<q0, q1, q2, q3> takes four coordinates, the scalar part first
// case repeated_parameter: kane: the four Euler parameters are four different coordinates
// case unit_norm_of_simple: unit_norm_needs_a_frame_oriented_by_euler_parameters<A>
// case held_first: kane: in speeds<...> the speeds that q' define come first, then kane::free_speed, then held rows
// case parameters_beyond_state: kane: the Euler parameters use a coordinate beyond the state
#include <kane/kane.hpp>

template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
#ifdef KANE_CASE_three_parameters
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>>> {};
#elif defined(KANE_CASE_repeated_parameter)
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<2>>> {};
#else
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
#endif
struct A : kane::frame<N, kane::simple<kane::axis::z, q<5>>> {};
inline constexpr auto w = kane::angular_velocity<N, B>();

#ifdef KANE_CASE_unit_norm_of_simple
using speeds = kane::speeds<dot(w, kane::e<B, 1>), dot(w, kane::e<B, 2>), dot(w, kane::e<B, 3>),
                            kane::dt(kane::q<5>), kane::unit_norm<A>>;
#elif defined(KANE_CASE_held_first)
using speeds = kane::speeds<kane::unit_norm<B>, dot(w, kane::e<B, 1>), dot(w, kane::e<B, 2>),
                            dot(w, kane::e<B, 3>), kane::dt(kane::q<5>)>;
#else
using speeds = kane::speeds<dot(w, kane::e<B, 1>), dot(w, kane::e<B, 2>), dot(w, kane::e<B, 3>),
                            kane::dt(kane::q<5>), kane::unit_norm<B>>;
#endif

double use() {
  kane::state<double, 5, 4> s;
  s.q = {1, 0, 0, 0, 0.3};
  s.u = {0.1, 0.2, 0.3, 0.4};
  kane::evaluator<kane::state<double, 5, 4>, kane::frames<A, B>, kane::level::velocity, speeds> ev;
  ev.update(s);
#ifdef KANE_CASE_parameters_beyond_state
  const kane::state<double, 3> small{};
#else
  const kane::state<double, 4> small{};
#endif
  return kane::express<N>(w, ev)[0] + kane::direction_cosines<N, B>(small)(0, 0);
}
