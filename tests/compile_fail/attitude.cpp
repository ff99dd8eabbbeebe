// Attitudes read from the state (kane::attitude): a source and three different free
// speeds of the evaluator's speed set; parameters within the state.
// Each case is a misuse (#ifdef) and its fix (#else).
// case without_its_speeds: a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<.*B>
// case without_speed_set: a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<.*B>
// case repeated_rate: kane: the three rates of an attitude are three different speeds
// case source_not_state: kane: attitude<Source, Rates> reads kane::rotation_matrix<K> or kane::unit_quaternion<K>
// case beyond_parameters: kane: the attitude is read from parameters beyond the state
// case rates_not_rates: kane: attitude<Source, Rates> turns at kane::body_rates<...> or kane::parent_rates<...>
// case rates_not_speeds: kane: body_rates<u1, u2, u3> takes three speeds
#include <kane/kane.hpp>

template <std::size_t I>
using u = kane::speed<I>;
struct N : kane::root_frame {};
#ifdef KANE_CASE_repeated_rate
using rates = kane::body_rates<u<1>, u<2>, u<1>>;
#elif defined(KANE_CASE_rates_not_rates)
using rates = kane::coordinate<1>;
#elif defined(KANE_CASE_rates_not_speeds)
using rates = kane::body_rates<u<1>, u<2>, kane::coordinate<3>>;
#else
using rates = kane::body_rates<u<1>, u<2>, u<3>>;
#endif
#ifdef KANE_CASE_source_not_state
struct B : kane::frame<N, kane::attitude<kane::coordinate<1>, rates>> {};
#else
struct B : kane::frame<N, kane::attitude<kane::unit_quaternion<1>, rates>> {};  // p1..p4
#endif

#ifdef KANE_CASE_without_its_speeds
using speeds = kane::qdot_speeds<3>;
#else
using speeds = kane::speeds<kane::free_speed, kane::free_speed, kane::free_speed>;
#endif
#ifdef KANE_CASE_beyond_parameters
using state = kane::state<double, 0, 3, 3>;
#else
using state = kane::state<double, 0, 3, 4>;
#endif
#ifdef KANE_CASE_without_speed_set
using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::velocity>;
#else
using evaluator = kane::evaluator<state, kane::frames<B>, kane::level::velocity, speeds>;
#endif

double use() {
  state s;
  s.u = {0.1, 0.2, 0.3};
  evaluator ev;
  ev.update(s);
  return kane::express<N>(kane::angular_velocity<N, B>(), ev)[0];
}
