// kane::motion computes Kane's sums at u' = 0, where it writes the bias accelerations as
// expressions with u' (and q'' where a speed is q') set to zero. kane::forward_dynamics at a state
// of any u' subtracts the partial velocities times u' from the accelerations instead. Both give
// u' = M^-1 f; here on systems whose angular accelerations at rest each rule writes out: a chain of
// turns by coordinates about crossed axes, speeds that are the components of an angular velocity
// in a turning frame or in the root, a spin below such a body, and speeds of which only some are q'.
#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <random>
#include <type_traits>

#include <kane/kane.hpp>

using kane::dot;
using kane::dt;
using kane::e;
using kane::literal;
using kane::q;
template <std::size_t I>
using c = kane::coordinate<I>;

namespace {

// u' of motion (at rest) against forward_dynamics at a random u' (the accelerations of the state)
template <class Sys, class Ev, class Fill>
void check(Fill fill, double tol) {
  using St = typename Ev::state_type;
  constexpr std::size_t nq = St::nq, nu = Ev::nu;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-1.5, 1.5);
  for (int k = 0; k < 8; ++k) {
    St s;
    for (auto& x : s.q) x = d(rng);
    if constexpr (std::is_void_v<typename Ev::speed_set>) {
      for (auto& x : s.qd) x = d(rng);
      for (auto& x : s.qdd) x = 3 * d(rng);
    } else {
      for (auto& x : s.u) x = d(rng);
      for (auto& x : s.ud) x = 3 * d(rng);
    }
    fill(s);
    kane::motion<Sys, Ev> rhs(s);
    std::array<double, nq + nu> x{}, dx{};
    for (std::size_t i = 0; i < nq; ++i) x[i] = s.q[i];
    for (std::size_t i = 0; i < nu; ++i)
      x[nq + i] = std::is_void_v<typename Ev::speed_set> ? s.qd[i] : s.u[i];
    rhs(x, dx, 0.0);
    REQUIRE(rhs.status() == kane::solve_status::ok);
    Ev ev;
    ev.update(s);
    const auto fd = kane::forward_dynamics<Sys>(ev);
    REQUIRE(fd.status == kane::solve_status::ok);
    double scale = 1;
    for (std::size_t i = 0; i < nu; ++i) scale = std::fmax(scale, std::fabs(fd.ud(Eigen::Index(i))));
    for (std::size_t i = 0; i < nu; ++i) CHECK(std::fabs(dx[nq + i] - fd.ud(Eigen::Index(i))) <= tol * scale);
  }
}

struct N : kane::root_frame {};
struct O : kane::origin<N> {};

// A about n3 by q1, B about a1 by q2, C about n2 by q3 (a sibling of A): the sums, not the tree.
namespace crossed {
struct A : kane::frame<N, kane::simple<kane::axis::z, c<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, c<2>>> {};
struct C : kane::frame<N, kane::simple<kane::axis::y, c<3>>> {};
struct Bo : kane::point<O, literal(0.7) * e<A, 1> + literal(0.4) * e<B, 2>> {};
struct Co : kane::point<Bo, literal(0.5) * e<C, 3>> {};
using system = kane::system<
    kane::rigid_body<B, Bo, literal(1.3),
                     kane::inertia<B, Bo, literal(0.11), literal(0.09), literal(0.07), literal(0.01),
                                   literal(-0.02), literal(0.015)>>,
    kane::rigid_body<C, Co, literal(0.8), kane::inertia<C, Co, literal(0.05), literal(0.06), literal(0.04)>>,
    kane::gravity<literal(-9.81) * e<N, 3>>>;
using evaluator = kane::evaluator<kane::state<double, 3, 3>, kane::frames<B, C>, kane::level::acceleration>;
}  // namespace crossed

// A about n3 by q1; B from A by Euler parameters q2..q5, its speeds ^N w^B . a_i (in a turning frame)
namespace in_a {
struct A : kane::frame<N, kane::simple<kane::axis::z, c<1>>> {};
struct B : kane::frame<A, kane::euler_parameters<c<2>, c<3>, c<4>, c<5>>> {};
struct Bo : kane::point<O, literal(0.6) * e<A, 1>> {};
struct P : kane::point<Bo, literal(0.3) * e<B, 1> + literal(0.2) * e<B, 3>> {};
inline constexpr auto w = kane::angular_velocity<N, B>();
using speeds = kane::speeds<dt(q<1>), dot(w, e<A, 1>), dot(w, e<A, 2>), dot(w, e<A, 3>), kane::unit_norm<B>>;
using system = kane::system<kane::rigid_body<B, Bo, literal(2.0),
                                             kane::inertia<B, Bo, literal(0.3), literal(0.4), literal(0.5),
                                                           literal(0.02), literal(0.01), literal(-0.03)>>,
                            kane::particle<P, literal(0.4)>, kane::gravity<literal(-9.81) * e<N, 3>>>;
using evaluator =
    kane::evaluator<kane::state<double, 5, 4>, kane::frames<B>, kane::level::acceleration, speeds>;
}  // namespace in_a

// a free body on Euler parameters with speeds ^N w^B . n_i (the root's), a wheel W spinning about b3
// at the free speed u7, a particle off its mass centre
namespace wheel {
struct B : kane::frame<N, kane::euler_parameters<c<1>, c<2>, c<3>, c<4>>> {};
struct W : kane::frame<B, kane::spin<kane::axis::z, kane::speed<7>>> {};
struct Bo : kane::point<O, q<5> * e<N, 1> + q<6> * e<N, 2> + q<7> * e<N, 3>> {};
struct P : kane::point<Bo, literal(0.25) * e<B, 2>> {};
inline constexpr auto w = kane::angular_velocity<N, B>();
using speeds = kane::speeds<dot(w, e<N, 1>), dot(w, e<N, 2>), dot(w, e<N, 3>), dt(q<5>), dt(q<6>), dt(q<7>),
                            kane::free_speed, kane::unit_norm<B>>;
using system = kane::system<
    kane::rigid_body<B, Bo, literal(10), kane::inertia<B, Bo, literal(1.2), literal(1.5), literal(1.9)>>,
    kane::rigid_body<W, Bo, literal(0.5), kane::inertia<B, Bo, literal(0.01), literal(0.01), literal(0.02)>>,
    kane::particle<P, literal(0.3)>>;
using evaluator =
    kane::evaluator<kane::state<double, 7, 7>, kane::frames<W>, kane::level::acceleration, speeds>;
}  // namespace wheel

// A about n3 by q1, B about a1 by q2, with u1 = q1' + q2', u2 = q2': q2'' = 0 at rest, q1'' not
namespace partial_rates {
struct A : kane::frame<N, kane::simple<kane::axis::z, c<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, c<2>>> {};
struct P1 : kane::point<O, literal(0.9) * e<A, 1>> {};
struct P2 : kane::point<P1, literal(0.6) * e<B, 2> + literal(0.3) * e<B, 3>> {};
using speeds = kane::speeds<dt(q<1>) + dt(q<2>), dt(q<2>)>;
using system = kane::system<
    kane::particle<P1, literal(1.1)>,
    kane::rigid_body<B, P2, literal(0.7), kane::inertia<B, P2, literal(0.02), literal(0.03), literal(0.025)>>,
    kane::gravity<literal(-9.81) * e<N, 3>>>;
using evaluator =
    kane::evaluator<kane::state<double, 2, 2>, kane::frames<B>, kane::level::acceleration, speeds>;
}  // namespace partial_rates

// Euler parameters of unit norm
template <std::size_t First>
auto unit_quaternion() {
  return [](auto& s) {
    double n = 0;
    for (std::size_t i = First; i < First + 4; ++i) n += s.q[i] * s.q[i];
    for (std::size_t i = First; i < First + 4; ++i) s.q[i] /= std::sqrt(n);
  };
}

}  // namespace

TEST_CASE("rest bias: turns by coordinates about crossed axes, u = q'") {
  check<crossed::system, crossed::evaluator>([](auto&) {}, 1e-12);
}

TEST_CASE("rest bias: speeds that are components of w in a turning frame") {
  check<in_a::system, in_a::evaluator>(unit_quaternion<1>(), 1e-12);
}

TEST_CASE("rest bias: a wheel spinning in a body whose speeds are components of w in the root") {
  check<wheel::system, wheel::evaluator>(unit_quaternion<0>(), 1e-12);
}

TEST_CASE("rest bias: speeds of which only some are coordinate rates") {
  check<partial_rates::system, partial_rates::evaluator>([](auto&) {}, 1e-12);
}
