// kane's implementation of the 6-revolute chain (arm6.hpp).
#include <kane/kane.hpp>

#include "arm6.hpp"

namespace {
template <std::size_t I>
using q = kane::coordinate<I>;
using kane::axis::x;
using kane::axis::y;
using kane::axis::z;

struct N : kane::root_frame {};
struct B1 : kane::frame<N, kane::simple<z, q<1>>> {};
struct B2 : kane::frame<B1, kane::simple<y, q<2>>> {};
struct B3 : kane::frame<B2, kane::simple<y, q<3>>> {};
struct B4 : kane::frame<B3, kane::simple<x, q<4>>> {};
struct B5 : kane::frame<B4, kane::simple<y, q<5>>> {};
struct B6 : kane::frame<B5, kane::simple<x, q<6>>> {};

struct O : kane::origin<N> {};
struct J2 : kane::point<O, 0.3 * kane::e<B1, 1>> {};
struct J3 : kane::point<J2, 0.25 * kane::e<B2, 1>> {};
struct J4 : kane::point<J3, 0.2 * kane::e<B3, 1>> {};
struct J5 : kane::point<J4, 0.15 * kane::e<B4, 1>> {};
struct J6 : kane::point<J5, 0.1 * kane::e<B5, 1>> {};
struct End : kane::point<J6, 0.05 * kane::e<B6, 1>> {};

using state = kane::state<double, 6>;

template <class V>
void store(const V& v, double* out) {
  out[0] = v[0], out[1] = v[1], out[2] = v[2];
}
}  // namespace

namespace arm6 {
void kane_pose(const input& in, output& out) {
  state s;
  s.q = in.q;
  kane::evaluator<state, kane::frames<B6>, kane::level::pose> ev;
  ev.update(s);
  Eigen::Map<Eigen::Matrix3d>(out.R) = ev.axes<B6>();
  store(kane::express<N>(kane::position<O, End>(), ev), out.p);
}

void kane_all(const input& in, output& out) {
  state s;
  s.q = in.q;
  s.qd = in.qd;
  s.qdd = in.qdd;
  kane::evaluator<state, kane::frames<B6>> ev;
  ev.update(s);
  Eigen::Map<Eigen::Matrix3d>(out.R) = ev.axes<B6>();
  store(kane::express<N>(kane::position<O, End>(), ev), out.p);
  store(kane::express<N>(kane::angular_velocity<N, B6>(), ev), out.w);
  store(kane::express<N>(kane::velocity<N, End>(), ev), out.v);
  store(kane::express<N>(kane::angular_acceleration<N, B6>(), ev), out.alpha);
  store(kane::express<N>(kane::acceleration<N, End>(), ev), out.a);
}
}  // namespace arm6
