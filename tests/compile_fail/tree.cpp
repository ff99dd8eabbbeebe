// Frame trees: no cycles, real parents and axes, joined frames only. Each case is a misuse (#ifdef)
// and its fix (#else).
// case cycle: kane: a frame.s parent must be declared .complete. before the frame
// case not_a_frame: kane: frame<Parent, Orientation> needs a frame as Parent
// case no_path: frames_of_two_trees_relate_them_through_a_common_root_frame<N, M>
// case zero_axis: kane: an axis direction must not be the zero vector
// case sequence: kane: a rotation sequence takes axes 1, 2, 3 with consecutive axes different
// case vec_of_non_frame: kane: vec<F> needs a frame F
#include <kane/kane.hpp>

using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct M : kane::root_frame {};
struct G : kane::frame<M, kane::simple<kane::axis::x, q2>> {};

#ifdef KANE_CASE_cycle
struct Y;
struct X : kane::frame<Y, kane::simple<kane::axis::z, q1>> {};
struct Y : kane::frame<X, kane::simple<kane::axis::z, q2>> {};
#else
struct X : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct Y : kane::frame<X, kane::simple<kane::axis::z, q2>> {};
#endif
#ifdef KANE_CASE_not_a_frame
struct H : kane::frame<int, kane::simple<kane::axis::z, q1>> {};
#else
struct H : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
#endif
#ifdef KANE_CASE_zero_axis
struct Z : kane::frame<N, kane::simple<kane::direction<0, 0, 0>, q1>> {};
#else
struct Z : kane::frame<N, kane::simple<kane::direction<0, 0, 1>, q1>> {};
#endif
#ifdef KANE_CASE_sequence
struct S : kane::frame<N, kane::body_fixed<3, 3, 1, q1, q2, q1>> {};
#else
struct S : kane::frame<N, kane::body_fixed<3, 2, 1, q1, q2, q1>> {};
#endif

double use() {
  kane::state<double, 2> s;
  double x = kane::direction_cosines<N, Y>(s)(0, 0) + kane::direction_cosines<N, H>(s)(0, 0);
  x += kane::direction_cosines<N, Z>(s)(0, 0) + kane::direction_cosines<N, S>(s)(0, 0);
#ifdef KANE_CASE_no_path
  x += kane::direction_cosines<A, G>(s)(0, 0);
#else
  x += kane::direction_cosines<A, N>(s)(0, 0) + kane::direction_cosines<G, M>(s)(0, 0);
#endif
#ifdef KANE_CASE_vec_of_non_frame
  kane::vec<double> p;
#else
  kane::vec<A> p;
#endif
  return x + p[0];
}
