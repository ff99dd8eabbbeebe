// The Whipple bicycle without contact coordinates: the rear wheel's centre known by its velocity,
// ^N w^Wr x rr r3 (its contact point at rest), every other point located from it. Four
// coordinates (yaw, roll, pitch, steer), six speeds, three constraints (the front wheel rolls, its
// contact stays on the ground). Its reduced equations and u' against SymPy's KanesMethod for the
// bicycle with contact coordinates (tests/data/gen_bicycle_dynamics.py): the rear contact's
// coordinates enter no equation, so both have the same Mr, fr and u'.
#include <array>
#include <catch2/catch.hpp>

#include "../examples/models/bicycle.hpp"
#include "data/sympy_bicycle_dynamics.hpp"

namespace {
namespace rolling_bicycle {
using kane::dot;
using kane::e;
using models::bicycle::c;
using models::bicycle::d;
using models::bicycle::lambda_;
using models::bicycle::o;
using models::bicycle::rf;
using models::bicycle::rr;
template <std::size_t I>
using q = kane::coordinate<I>;

struct N : kane::root_frame {};
struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};  // yaw
struct R : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};  // roll
struct P : kane::frame<R, kane::simple<kane::axis::y, q<3>>> {};  // pitch
struct H : kane::frame<P, kane::simple<kane::axis::y, lambda_>> {};
struct F : kane::frame<H, kane::simple<kane::axis::x, q<4>>> {};  // steer
struct Wr : kane::frame<H, kane::spin<kane::axis::y, kane::speed<5>>> {};
struct Wf : kane::frame<F, kane::spin<kane::axis::y, kane::speed<6>>> {};

inline constexpr auto g = dot(e<F, 2>, e<Y, 3>);
struct Dr : kane::point_by_velocity<N, kane::cross(kane::angular_velocity<N, Wr>(), rr* e<R, 3>)> {};
struct S : kane::point<Dr, d * e<H, 3>> {};
struct Df : kane::point<S, c * e<F, 1> + o * e<F, 3>> {};
struct Cf : kane::point<Df, rf / kane::sqrt(1 - g * g) * (g * e<F, 2> - e<Y, 3>)> {};
struct Bf : kane::point<Df, rf / kane::sqrt(1 - g * g) * (g * e<F, 2> - e<Y, 3>)> {};

inline constexpr auto ground = dot(rr * e<R, 3> + kane::position<Dr, Cf>(), e<N, 3>);  // Cf above Cr
using speeds = kane::speeds<kane::dt(q<1>{}), kane::dt(q<2>{}), kane::dt(q<3>{}), kane::dt(q<4>{}),
                            kane::free_speed, kane::free_speed>;
inline constexpr auto v_bf = kane::body_point_velocity<N, Wf, Df, Bf>();
using rolling = kane::nonholonomic<speeds, kane::dependent<1, 3, 6>, dot(v_bf, e<Y, 1>), dot(v_bf, e<Y, 2>),
                                   kane::dt(ground)>;

namespace b = models::bicycle;  // the benchmark's bodies, parameters p7..p27 by name
struct Bo : kane::point<Dr, b::xB * e<H, 1> + b::zB * e<H, 3>> {};
struct Ho : kane::point<Df, b::xH * e<F, 1> + b::zH * e<F, 3>> {};
using b::zero;
using system = kane::system<
    kane::rigid_body<Wr, Dr, b::mR, kane::inertia<H, Dr, b::IRxx, b::IRyy, b::IRxx>>,
    kane::rigid_body<H, Bo, b::mB, kane::inertia<H, Bo, b::IB11, b::IB22, b::IB33, zero, zero, b::IB31>>,
    kane::rigid_body<F, Ho, b::mH, kane::inertia<F, Ho, b::IH11, b::IH22, b::IH33, zero, zero, b::IH31>>,
    kane::rigid_body<Wf, Df, b::mF, kane::inertia<F, Df, b::IFxx, b::IFyy, b::IFxx>>,
    kane::gravity<-b::gravity * e<N, 3>>>;
using state = kane::state<double, 4, 6, 27>;
using evaluator = kane::evaluator<state, kane::frames<Wr, Wf>, kane::level::acceleration, speeds>;
}  // namespace rolling_bicycle
}  // namespace

TEST_CASE("bicycle without contact coordinates: reduced equations and u' against SymPy's KanesMethod") {
  namespace rb = rolling_bicycle;
  for (const auto& x : sympy_bicycle_dynamics::cases) {
    rb::state s;
    for (std::size_t i = 0; i < 27; ++i) s.p[i] = sympy_bicycle_dynamics::p[i];
    for (std::size_t i = 0; i < 4; ++i) s.q[i] = x.q[2 + i];  // yaw, roll, pitch, steer
    for (std::size_t i = 0; i < 6; ++i) s.u[i] = x.u[2 + i];
    rb::evaluator ev;
    ev.update(s);
    CHECK(kane::evaluate(rb::ground, ev) == Approx(0).margin(1e-14));
    const auto sol = kane::solve_constraints<rb::rolling>(ev);
    REQUIRE(sol.status == kane::solve_status::ok);
    const Eigen::Vector3d ind(x.u[3], x.u[5], x.u[6]);  // roll, steer and rear wheel rates
    const Eigen::Vector3d dep = sol.A * ind + sol.B;    // yaw, pitch and front wheel rates
    CHECK(dep(0) == Approx(x.u[2]).margin(1e-13).epsilon(1e-12));
    CHECK(dep(1) == Approx(x.u[4]).margin(1e-13).epsilon(1e-12));
    CHECK(dep(2) == Approx(x.u[7]).margin(1e-13).epsilon(1e-12));
    const auto red = kane::reduced_mass_matrix_and_forcing<rb::system, rb::rolling>(ev, sol);
    REQUIRE(red.reduced.status == kane::solve_status::ok);
    for (int r = 0; r < 3; ++r) {
      CHECK(red.reduced.f(r) == Approx(x.fr[r]).margin(1e-12).epsilon(1e-12));
      for (int k = 0; k < 3; ++k)
        CHECK(red.reduced.M(r, k) == Approx(x.Mr[r][k]).margin(1e-13).epsilon(1e-12));
    }
    const auto [ui, st] = kane::speed_derivatives(red.reduced);
    REQUIRE(st == kane::solve_status::ok);
    const Eigen::Matrix<double, 6, 1> ud = red.T * ui + red.b;
    for (int i = 0; i < 6; ++i) CHECK(ud(i) == Approx(x.ud[2 + i]).margin(1e-12).epsilon(1e-12));
    CHECK(kane::kinetic_energy<rb::system>(ev) == Approx(x.T).epsilon(1e-13));
  }
}
