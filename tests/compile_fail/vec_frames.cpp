// Components expressed in different frames do not mix.
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
  kane::vec<N> r = pN + kane::express<N>(pA, s);  // the fix: express first
#ifdef KANE_CASE_plus
  r = pN + pA;
#endif
#ifdef KANE_CASE_minus
  pA = pA - pN;
#endif
#ifdef KANE_CASE_dot
  return kane::dot(pN, pA);
#endif
#ifdef KANE_CASE_cross
  pA = kane::cross(pA, pN);
#endif
#ifdef KANE_CASE_equal
  return pN == pA ? 1.0 : 0.0;
#endif
#ifdef KANE_CASE_assign
  r = pA;
#endif
#ifdef KANE_CASE_construct
  kane::vec<A> q = pN;
  return q[0];
#endif
  return r[0] + pA[0];
}
