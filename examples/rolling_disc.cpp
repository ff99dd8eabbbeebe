// The rolling disc: yaw q1 about n3 (frame Y), lean q2 about y1 (L), spin q3
// about l2 (R, the disc); radius r. Speeds: u_i = ^N w^R . l_i.
// Three coordinates: rolling without slip makes the contact point's velocity
// zero, so the centre moves with ^N w^R x r l3.
// Five coordinates: the contact point at q4 n1 + q5 n2, u4 = q4', u5 = q5';
// two nonholonomic constraints (the disc's contact point is at rest in N)
// make u4, u5 dependent.
#include <cstdio>

#include <kane/kane.hpp>

using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct r_ : kane::parameter<1> {};
inline constexpr r_ r;

struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};  // yaw
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};  // lean
struct R : kane::frame<L, kane::simple<kane::axis::y, q<3>>> {};  // spin: the disc

inline constexpr auto w = kane::angular_velocity<N, R>();
using speeds3 = kane::speeds<dot(w, e<L, 1>), dot(w, e<L, 2>), dot(w, e<L, 3>)>;

struct C : kane::origin<N> {};  // the contact point, at rest
struct Centre : kane::point<C, r * e<L, 3>> {};
inline constexpr auto v_centre = kane::body_point_velocity<N, R, C, Centre>();

struct O : kane::origin<N> {};
struct Contact : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2>> {};
struct Centre5 : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre5, -r * e<L, 3>> {};  // the disc's point at the contact
using speeds5 = kane::angular_velocity_speeds<N, R, L, kane::dt(kane::q<4>), kane::dt(kane::q<5>)>;
inline constexpr auto v_below = kane::body_point_velocity<N, R, Centre5, Below>();
using rolling =
    kane::nonholonomic<speeds5, kane::dependent<4, 5>, dot(v_below, e<N, 1>), dot(v_below, e<N, 2>)>;

template <class M>
void print(const char* title, const M& m) {
  std::printf("%s\n", title);
  for (int i = 0; i < m.rows(); ++i) {
    std::printf("   ");
    for (int j = 0; j < m.cols(); ++j) std::printf(" % .6f", m(i, j));
    std::printf("\n");
  }
}

int main() {
  kane::state<double, 3, 3, 1> s3;
  s3.q = {0.3, 0.2, 1.0};
  s3.u = {0.5, -1.5, 0.8};
  s3.p = {0.25};
  kane::evaluator<decltype(s3), kane::frames<R>, kane::level::velocity, speeds3> ev3;
  ev3.update(s3);
  const auto V3 = kane::partial_velocities<N>(v_centre, ev3);  // v_r of the centre, in N
  print("partial velocities of the centre (columns v_1 v_2 v_3, in N):", V3);
  print("partial angular velocities of the disc (w_1 w_2 w_3, in N):", kane::partial_velocities<N>(w, ev3));

  kane::state<double, 5, 5, 1> s5;
  s5.q = {0.3, 0.2, 1.0, 2.0, -1.0};
  s5.u = {0.5, -1.5, 0.8, 0.0, 0.0};
  s5.p = {0.25};
  kane::evaluator<decltype(s5), kane::frames<R>, kane::level::velocity, speeds5> ev5;
  ev5.update(s5);
  const auto sol = kane::solve_constraints<rolling>(ev5);  // u4, u5 = A (u1 u2 u3) + B
  if (sol.status != kane::solve_status::ok) return 1;
  print("A (rows u4 u5, columns u1 u2 u3):", sol.A);
  const auto V5 = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Centre5>(), ev5, sol);
  print("nonholonomic partial velocities of the centre, five coordinates (in N):", V5);
  const double gap = (V5 - V3).cwiseAbs().maxCoeff();
  std::printf("largest difference to the three-coordinate disc: %.1e\n", gap);
  return gap < 1e-12 ? 0 : 1;
}
