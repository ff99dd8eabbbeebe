// Components expressed in different frames do not mix.
// case plus: deleted && frames_differ_express_one_in_the_others_frame_first && LeftFrame = N. RightFrame = A
// case minus: deleted && frames_differ_express_one_in_the_others_frame_first && LeftFrame = A. RightFrame = N
// case dot: deleted && frames_differ_express_one_in_the_others_frame_first && dot && LeftFrame = N. RightFrame = A
// case cross: deleted && frames_differ_express_one_in_the_others_frame_first && cross && LeftFrame = A. RightFrame = N
// case equal: deleted && frames_differ_express_one_in_the_others_frame_first && LeftFrame = N. RightFrame = A
// case assign: deleted && frames_differ_use_express_to_change_frame && (G = A. F = N|vec<A.*vec<N)
// case construct: deleted && frames_differ_use_express_to_change_frame && (G = N. F = A|vec<N.*vec<A)
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
