// Three common mistakes, compiled as a user compiles (no precompiled header, default flags): the
// first error, up to the second, stays under 4 KB and names the rule and its fix in its first five
// lines. Each case is a misuse (#ifdef) and its fix (#else).
// first sum_of_two_frames: frames_differ_express_one_in_the_others_frame_first<N, A> && call_kane_express<N>
// first inertia_in_turning_frame: inertia_given_in_a_frame_that_turns_relative_to_the_body<A, B> && give_the_inertia_in_the_body_frame<B>
// first state_too_small: a_frame_turns_by_a_coordinate_beyond_the_state<kane::coordinate<2 && declare_kane_state_with_nq_at_least<2>
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, kane::coordinate<2>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::literal(0.5) * kane::e<B, 3>> {};

double sum(const kane::state<double, 2>& s) {
  const kane::vec<N> pN(1, 2, 3);
  const kane::vec<A> pA(4, 5, 6);
#ifdef KANE_CASE_sum_of_two_frames
  const kane::vec<N> r = pN + pA;
#else
  const kane::vec<N> r = pN + kane::express<N>(pA, s);
#endif
  return r[0];
}

#ifdef KANE_CASE_inertia_in_turning_frame
using inertia = kane::inertia<A, Bo, kane::literal(1.0), kane::literal(2.0), kane::literal(3.0)>;
#else
using inertia = kane::inertia<B, Bo, kane::literal(1.0), kane::literal(2.0), kane::literal(3.0)>;
#endif
using top = kane::system<kane::rigid_body<B, Bo, kane::literal(1.0), inertia>,
                         kane::gravity<kane::literal(-9.81) * kane::e<N, 3>>>;
double motion() {
  kane::motion<top> f(kane::state_of<top>{});
  std::array<double, 4> x{0.1, 0.2, 0.0, 0.0}, dx{};
  f(x, dx, 0.0);
  return dx[3];
}

#ifdef KANE_CASE_state_too_small
using state = kane::state<double, 1>;
#else
using state = kane::state<double, 2>;
#endif
double energy() {
  kane::evaluator<state, kane::frames<B>> ev;
  ev.update(state{});
  return kane::kinetic_energy<top>(ev);
}
