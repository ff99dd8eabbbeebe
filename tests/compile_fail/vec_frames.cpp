// Components expressed in different frames do not mix. Each case is a misuse (#ifdef) and its
// fix (#else): express one operand in the other's frame first.
// case plus: frames_differ_express_one_in_the_others_frame_first<N, A>
// case minus: frames_differ_express_one_in_the_others_frame_first<A, N>
// case dot: frames_differ_express_one_in_the_others_frame_first<N, A>
// case cross: frames_differ_express_one_in_the_others_frame_first<A, N>
// case equal: frames_differ_express_one_in_the_others_frame_first<N, A>
// case assign: frames_differ_use_express_to_change_frame<A, N>
// case construct: frames_differ_use_express_to_change_frame<N, A>
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};

double use() {
  kane::state<double, 1> s;
  kane::vec<N> pN(1, 2, 3);
  kane::vec<A> pA(4, 5, 6);
  kane::vec<N> r;
  double x = 0;
#ifdef KANE_CASE_plus
  r = pN + pA;
#else
  r = pN + kane::express<N>(pA, s);
#endif
#ifdef KANE_CASE_minus
  pA = pA - pN;
#else
  pA = pA - kane::express<A>(pN, s);
#endif
#ifdef KANE_CASE_dot
  x += kane::dot(pN, pA);
#else
  x += kane::dot(kane::express<A>(pN, s), pA);
#endif
#ifdef KANE_CASE_cross
  pA = kane::cross(pA, pN);
#else
  pA = kane::cross(pA, kane::express<A>(pN, s));
#endif
#ifdef KANE_CASE_equal
  x += pN == pA ? 1.0 : 0.0;
#else
  x += pN == kane::express<N>(pA, s) ? 1.0 : 0.0;
#endif
#ifdef KANE_CASE_assign
  r = pA;
#else
  r = kane::express<N>(pA, s);
#endif
#ifdef KANE_CASE_construct
  kane::vec<A> q = pN;
#else
  kane::vec<A> q = kane::express<A>(pN, s);
#endif
  return x + r[0] + pA[0] + q[0];
}
