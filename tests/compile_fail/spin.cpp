// Frames that spin by a free speed (kane::spin): only the spin axis is known, the
// speed is a free speed of the evaluator's speed set, free speeds follow the speeds q' define.
// Each case is a misuse (#ifdef) and its fix (#else).
// case off_axis: a_spinning_frame_has_no_known_axes_but_its_spin_axis<.*W>
// case express_in_spin: a_spinning_frame_has_no_known_axes_but_its_spin_axis<.*W>
// case frame_below_spin: a_spinning_frame_has_no_known_axes_but_its_spin_axis<.*W>
// case without_speed_set: a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<.*W>
// case speed_not_free: a_frame_turns_at_free_speeds_of_the_evaluators_speed_set<.*W>
// case free_speed_first: kane: in speeds<...> the speeds that q' define come first, then kane::free_speed
// case spin_by_coordinate: kane: spin<Axis, U> turns at a generalized speed U = kane::speed<r>
#include <kane/kane.hpp>

template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
#ifdef KANE_CASE_spin_by_coordinate
struct W : kane::frame<A, kane::spin<kane::axis::y, q<2>>> {};
#else
struct W : kane::frame<A, kane::spin<kane::axis::y, kane::speed<2>>> {};  // a wheel
#endif
#ifdef KANE_CASE_frame_below_spin
struct V : kane::frame<W, kane::simple<kane::axis::x, q<1>>> {};  // a valve on the wheel
#else
struct V : kane::frame<A, kane::simple<kane::axis::x, q<1>>> {};
#endif

#ifdef KANE_CASE_speed_not_free
using speeds = kane::qdot_speeds<2>;
using state = kane::state<double, 2, 2>;
#elif defined(KANE_CASE_free_speed_first)
using speeds = kane::speeds<kane::free_speed, kane::dt(kane::q<1>)>;
using state = kane::state<double, 1, 2>;
#else
using speeds = kane::speeds<kane::dt(kane::q<1>), kane::free_speed>;
using state = kane::state<double, 1, 2>;
#endif
#ifdef KANE_CASE_without_speed_set
using evaluator = kane::evaluator<state, kane::frames<W, V>, kane::level::velocity>;
#else
using evaluator = kane::evaluator<state, kane::frames<W, V>, kane::level::velocity, speeds>;
#endif

double use() {
  state s;
  s.u = {0.1, 2.0};
  evaluator ev;
  ev.update(s);
#ifdef KANE_CASE_off_axis
  const auto x = kane::e<W, 1>;  // its angle is ignorable: not known
#else
  const auto x = kane::e<W, 2>;  // the spin axis, a2
#endif
#ifdef KANE_CASE_express_in_spin
  const auto v = kane::express<W>(kane::angular_velocity<N, W>(), ev);
#else
  const auto v = kane::express<A>(kane::angular_velocity<N, W>(), ev);
#endif
  return kane::express<N>(x, ev)[0] + v[1] + kane::express<N>(kane::e<V, 2>, ev)[0];
}
