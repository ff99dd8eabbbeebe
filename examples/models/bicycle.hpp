// The kinematics of the Whipple bicycle (Meijaard et al. 2007), as in SymPy's
// test_bicycle (sympy/physics/mechanics/tests/test_kane3.py), without fake
// coordinates: the wheels spin at free speeds, their angles are ignorable.
//
// Frames: yaw q3 about n3 (Y), roll q4 about y1 (R), pitch q5 about r2 (P), the
// head-tube angle lambda about p2, a constant rotation by a parameter (H, the rear
// frame), steer q6 about h1 (F, the fork); the rear wheel spins about h2 at u7
// (Wr), the front wheel about f2 at u8 (Wf). n3 points up.
// Points: the rear contact at q1 n1 + q2 n2, the rear centre rr r3 above it, the
// steer axis point d h3 further, the front centre c f1 + o f3 from there, the front
// contact rf (g f2 - y3) / sqrt(1 - g^2) from the front centre, g = f2 . y3.
// Constraints: the front contact on the ground, f = r^O,Cf . n3 = 0, makes the pitch
// q5 dependent; rolling of both wheels (their contact points at rest in y1 and y2)
// and df/dt = 0 make u1, u2 (the rear contact), u3 (yaw), u5 (pitch) and u8 (front
// wheel) dependent on u4 (roll), u6 (steer) and u7 (rear wheel).
#pragma once

#include <cmath>

#include <kane/kane.hpp>

namespace models::bicycle {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct rf_ : kane::parameter<1> {};      // front wheel radius
struct rr_ : kane::parameter<2> {};      // rear wheel radius
struct lambda_ : kane::parameter<3> {};  // head-tube angle from the rear frame's pitch axis
struct o_ : kane::parameter<4> {};       // fork offset
struct c_ : kane::parameter<5> {};       // fork length
struct d_ : kane::parameter<6> {};       // frame length
inline constexpr rf_ rf;
inline constexpr rr_ rr;
inline constexpr lambda_ lambda;
inline constexpr o_ o;
inline constexpr c_ c;
inline constexpr d_ d;

struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<3>>> {};
struct R : kane::frame<Y, kane::simple<kane::axis::x, q<4>>> {};
struct P : kane::frame<R, kane::simple<kane::axis::y, q<5>>> {};
struct H : kane::frame<P, kane::simple<kane::axis::y, lambda_>> {};
struct F : kane::frame<H, kane::simple<kane::axis::x, q<6>>> {};
struct Wr : kane::frame<H, kane::spin<kane::axis::y, kane::speed<7>>> {};
struct Wf : kane::frame<F, kane::spin<kane::axis::y, kane::speed<8>>> {};

inline constexpr auto g = dot(e<F, 2>, e<Y, 3>);
struct O : kane::origin<N> {};
struct Cr : kane::point<O, kane::q<1> * e<N, 1> + kane::q<2> * e<N, 2>> {};
struct Dr : kane::point<Cr, rr * e<R, 3>> {};  // the rear wheel's centre
struct S : kane::point<Dr, d * e<H, 3>> {};
struct Df : kane::point<S, c * e<F, 1> + o * e<F, 3>> {};  // the front wheel's centre
struct Cf : kane::point<Df, rf / kane::sqrt(1 - g * g) * (g * e<F, 2> - e<Y, 3>)> {};
struct Br : kane::point<Dr, -rr * e<R, 3>> {};  // the rear wheel's point at its contact
struct Bf : kane::point<Df, rf / kane::sqrt(1 - g * g) * (g * e<F, 2> - e<Y, 3>)> {};  // the front's

inline constexpr auto ground = dot(kane::position<O, Cf>(), e<N, 3>);
using pitch = kane::holonomic<kane::dependent_coordinates<5>, ground>;
using speeds =
    kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<2>), kane::dt(kane::q<3>), kane::dt(kane::q<4>),
                 kane::dt(kane::q<5>), kane::dt(kane::q<6>), kane::free_speed, kane::free_speed>;
inline constexpr auto v_br = kane::body_point_velocity<N, Wr, Dr, Br>();
inline constexpr auto v_bf = kane::body_point_velocity<N, Wf, Df, Bf>();
using rolling =
    kane::nonholonomic<speeds, kane::dependent<1, 2, 3, 5, 8>, dot(v_br, e<Y, 1>), dot(v_br, e<Y, 2>),
                       dot(v_bf, e<Y, 1>), dot(v_bf, e<Y, 2>), kane::dt(ground)>;
using state = kane::state<double, 6, 8, 6>;
using evaluator = kane::evaluator<state, kane::frames<Wr, Wf>, kane::level::velocity, speeds>;

// The bodies of the benchmark (Meijaard et al. 2007, Table 1, in this model's frames and
// parameters: tests/data/gen_bicycle_dynamics.py), p7..p27 by name: gravity; the rear wheel
// (mass, moments about its centre in H, where it spins), the rear frame with rider (mass at Bo,
// inertia in H), the front frame (mass at Ho, inertia in F), the front wheel (moments in F).
inline constexpr kane::parameter<7> gravity{};
inline constexpr kane::parameter<8> mR{};  // rear wheel
inline constexpr kane::parameter<9> IRxx{};
inline constexpr kane::parameter<10> IRyy{};
inline constexpr kane::parameter<11> mB{};  // rear frame: mass, Bo = Dr + xB h1 + zB h3, inertia
inline constexpr kane::parameter<12> xB{};
inline constexpr kane::parameter<13> zB{};
inline constexpr kane::parameter<14> IB11{};
inline constexpr kane::parameter<15> IB22{};
inline constexpr kane::parameter<16> IB33{};
inline constexpr kane::parameter<17> IB31{};
inline constexpr kane::parameter<18> mH{};  // front frame: mass, Ho = Df + xH f1 + zH f3, inertia
inline constexpr kane::parameter<19> xH{};
inline constexpr kane::parameter<20> zH{};
inline constexpr kane::parameter<21> IH11{};
inline constexpr kane::parameter<22> IH22{};
inline constexpr kane::parameter<23> IH33{};
inline constexpr kane::parameter<24> IH31{};
inline constexpr kane::parameter<25> mF{};  // front wheel
inline constexpr kane::parameter<26> IFxx{};
inline constexpr kane::parameter<27> IFyy{};
struct Bo : kane::point<Dr, xB * e<H, 1> + zB * e<H, 3>> {};
struct Ho : kane::point<Df, xH * e<F, 1> + zH * e<F, 3>> {};
inline constexpr kane::constant<0> zero{};
using system =
    kane::system<kane::rigid_body<Wr, Dr, mR, kane::inertia<H, Dr, IRxx, IRyy, IRxx>>,
                 kane::rigid_body<H, Bo, mB, kane::inertia<H, Bo, IB11, IB22, IB33, zero, zero, IB31>>,
                 kane::rigid_body<F, Ho, mH, kane::inertia<F, Ho, IH11, IH22, IH33, zero, zero, IH31>>,
                 kane::rigid_body<Wf, Df, mF, kane::inertia<F, Df, IFxx, IFyy, IFxx>>,
                 kane::gravity<-gravity * e<N, 3>>>;
using dynamics_state = kane::state<double, 6, 8, 27>;
using dynamics_evaluator =
    kane::evaluator<dynamics_state, kane::frames<Wr, Wf>, kane::level::acceleration, speeds>;

// Table 1 of Meijaard et al. (2007) in the parameters above. The benchmark's frame (x
// forward, y right, z down, upright) is N with y and z reversed; upright, pitch is 0 and
// H and F are N turned about n2 by lambda: (I)_jk = h_j . I . h_k, positions likewise.
inline dynamics_state benchmark_parameters() {
  const double w = 1.02, trail = 0.08, tilt = M_PI / 10, rR = 0.3, rF = 0.35, hta = M_PI / 2 - tilt;
  const double rake = -(trail * std::sin(hta) - rF * std::cos(hta)), cl = std::cos(hta), sl = std::sin(hta);
  // components along h1 = (c, 0, -s) and h3 = (s, 0, c) of (x, 0, z) in N
  const auto along1 = [&](double x, double z) { return cl * x - sl * z; };
  const auto along3 = [&](double x, double z) { return sl * x + cl * z; };
  struct moments {
    double i11, i22, i33, i31;
  };
  const auto in_h = [&](double ixx, double iyy, double izz, double ixz) {  // Table 1's xz is -ixz in N
    return moments{cl * cl * ixx - 2 * cl * sl * -ixz + sl * sl * izz, iyy,
                   sl * sl * ixx + 2 * sl * cl * -ixz + cl * cl * izz,
                   sl * cl * ixx + (cl * cl - sl * sl) * -ixz - cl * sl * izz};
  };
  const moments rear = in_h(9.2, 11, 2.8, 2.4), front = in_h(0.05892, 0.06, 0.00708, -0.00756);
  dynamics_state st;
  st.p = {rF,
          rR,
          hta,
          rake,
          w * cl - (rF - rR) * sl,
          w * sl - (rake - (rF - rR) * cl),
          9.81,
          2,
          0.0603,
          0.12,
          85,
          along1(0.3, 0.9 - rR),
          along3(0.3, 0.9 - rR),
          rear.i11,
          rear.i22,
          rear.i33,
          rear.i31,
          4,
          along1(0.9 - w, 0.7 - rF),
          along3(0.9 - w, 0.7 - rF),
          front.i11,
          front.i22,
          front.i33,
          front.i31,
          3,
          0.1405,
          0.28};
  return st;
}
}  // namespace models::bicycle
