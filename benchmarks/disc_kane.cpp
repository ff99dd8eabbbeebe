// kane's rolling disc (disc.hpp).
#include <kane/kane.hpp>

#include "disc.hpp"

namespace {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct r_ : kane::parameter<1> {};
inline constexpr r_ r;

struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};
struct R : kane::frame<L, kane::simple<kane::axis::y, q<3>>> {};
inline constexpr auto w = kane::angular_velocity<N, R>();

struct O : kane::origin<N> {};
struct Contact : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2>> {};
struct Centre : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre, -r * e<L, 3>> {};
using speeds5 = kane::angular_velocity_speeds<N, R, L, kane::dt(kane::q<4>), kane::dt(kane::q<5>)>;
inline constexpr auto v_below = kane::body_point_velocity<N, R, Centre, Below>();
using rolling =
    kane::nonholonomic<speeds5, kane::dependent<4, 5>, dot(v_below, e<N, 1>), dot(v_below, e<N, 2>)>;
using state = kane::state<double, 5, 5, 1>;
}  // namespace

void disc::kane_partials(const input& in, output& out) {
  state s;
  s.q = in.q;
  s.u = in.u;
  s.p = {in.r};
  kane::evaluator<state, kane::frames<R>, kane::level::velocity, speeds5> ev;
  ev.update(s);
  const auto sol = kane::solve_constraints<rolling>(ev);
  const auto V = kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Centre>(), ev, sol);
  Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(out.A) = sol.A;
  Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(out.V) = V;
}
