// Direction cosines compose and apply only along matching frames. Each case is a misuse (#ifdef)
// and its fix (#else).
// case compose: dcm_product_needs_left_from_frame_equal_right_to_frame<A, B>
// case apply: dcm_applies_only_to_components_in_its_from_frame<N, B>
#include <kane/kane.hpp>

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, kane::coordinate<2>>> {};

double use() {
  kane::state<double, 2> s;
  const kane::dcm<N, A> NPA = kane::direction_cosines<N, A>(s);
  const kane::dcm<A, B> APB = kane::direction_cosines<A, B>(s);
  const kane::dcm<N, B> NPB = APB * NPA;  // ^N P^B = ^A P^B . ^N P^A
  kane::vec<A> pA = NPA * kane::vec<N>(1, 2, 3);
#ifdef KANE_CASE_compose
  const auto wrong = APB * APB;
  (void)wrong;
#else
  const auto right = APB * NPA;
  (void)right;
#endif
#ifdef KANE_CASE_apply
  pA = NPA * kane::vec<B>(1, 2, 3);
#else
  pA = NPA * kane::vec<N>(1, 2, 3);
#endif
  return NPB(0, 0) + pA[0];
}
