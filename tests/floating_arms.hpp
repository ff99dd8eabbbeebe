// A floating base on Euler parameters with body rates, carrying two spatial arms of Links links
// (one link: 9 coordinates, 8 speeds; eight: 23 and 22). Its speeds are free_body_speeds followed
// by the joints' q', so its dynamics take the recursive passes with a free joint. Inputs: a thrust
// along b3 and a torque pair at each shoulder.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <type_traits>

#include <kane/kane.hpp>

#include "differences.hpp"

namespace floating_arms {
using kane::dot;
using kane::dt;
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;

struct N : kane::root_frame {};
struct B : kane::frame<N, kane::euler_parameters<q<1>, q<2>, q<3>, q<4>>> {};
struct O : kane::origin<N> {};
struct Bo : kane::point<O, kane::position_coordinates<N, 5>> {};

constexpr double length(std::size_t k) { return 0.12 + 0.03 * double((k * 5) % 4); }
constexpr double mass(std::size_t k) { return 0.5 + 0.15 * double((k * 3) % 5); }
template <std::size_t K>
using axis_of = std::conditional_t<K % 3 == 1, kane::axis::z,
                                   std::conditional_t<K % 3 == 2, kane::axis::y, kane::axis::x>>;
// link K (1 .. Links) of arm A (0, 1), turned by q_(7 + Links A + K) about z, y, x, ... of the link before
template <std::size_t Links, std::size_t A, std::size_t K>
struct L;
template <std::size_t Links, std::size_t A, std::size_t K>
using parent = std::conditional_t<K == 1, B, L<Links, A, K - 1>>;
template <std::size_t Links, std::size_t A, std::size_t K>
struct L : kane::frame<parent<Links, A, K>, kane::simple<axis_of<K>, q<7 + Links * A + K>>> {};
// joint K of arm A: the shoulder at -+0.25 b2 from the base's centre, then along x of each link
template <std::size_t Links, std::size_t A, std::size_t K>
struct J : kane::point<J<Links, A, K - 1>, literal(length(K - 1)) * e<L<Links, A, K - 1>, 1>> {};
template <std::size_t Links, std::size_t A>
struct J<Links, A, 1> : kane::point<Bo, literal(A == 0 ? -0.25 : 0.25) * e<B, 2>> {};
template <std::size_t Links, std::size_t A, std::size_t K>
struct C : kane::point<J<Links, A, K>, literal(length(K) / 2) * e<L<Links, A, K>, 1> +
                                           literal(0.01) * e<L<Links, A, K>, 3>> {};
template <std::size_t Links, std::size_t A, std::size_t K>
using link = kane::rigid_body<
    L<Links, A, K>, C<Links, A, K>, literal(mass(K)),
    kane::inertia<L<Links, A, K>, C<Links, A, K>, literal(0.004 * mass(K)), literal(0.006 * mass(K)),
                  literal(0.007 * mass(K)), literal(0.0004 * mass(K)), literal(-0.0003 * mass(K)),
                  literal(0.0002 * mass(K))>>;
using base =
    kane::rigid_body<B, Bo, literal(6.0),
                     kane::inertia<B, Bo, literal(0.08), literal(0.05), literal(0.1), literal(0.004)>>;

template <std::size_t Links, class>
struct items;
template <std::size_t Links, std::size_t... K>
struct items<Links, std::index_sequence<K...>> {
  using type =
      kane::system<base, link<Links, 0, K + 1>..., link<Links, 1, K + 1>...,
                   kane::gravity<literal(-9.81) * e<N, 3>>, kane::force<Bo, kane::r<1> * e<B, 3>>,  // thrust
                   kane::torque<L<Links, 0, 1>, kane::r<2> * e<B, 3>>, kane::torque<B, -kane::r<2> * e<B, 3>>,
                   kane::torque<L<Links, 1, 1>, kane::r<3> * e<B, 3>>,
                   kane::torque<B, -kane::r<3> * e<B, 3>>>;
};
template <class>
struct speed_set;
template <std::size_t... I>  // body rates, the centre's q5' .. q7', every joint's q'
struct speed_set<std::index_sequence<I...>> {
  using type =
      kane::speeds<dot(kane::angular_velocity<N, B>(), e<B, 1>), dot(kane::angular_velocity<N, B>(), e<B, 2>),
                   dot(kane::angular_velocity<N, B>(), e<B, 3>), dt(q<5 + I>{})..., kane::unit_norm<B>>;
};

template <std::size_t Links>
struct model {
  using system = typename items<Links, std::make_index_sequence<Links>>::type;
  using speeds = typename speed_set<std::make_index_sequence<3 + 2 * Links>>::type;
  using state = kane::state_of<system, speeds>;
  using evaluator = kane::system_evaluator<system, speeds>;
  using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>>;
};

// A state: unit Euler parameters, q, u and u' in -1..1, a thrust and two shoulder torques.
template <class State>
State sample(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  State s;
  for (auto& x : s.q) x = d(rng);
  for (auto& x : s.u) x = d(rng);
  for (auto& x : s.ud) x = d(rng);
  const double norm = std::sqrt(s.q[0] * s.q[0] + s.q[1] * s.q[1] + s.q[2] * s.q[2] + s.q[3] * s.q[3]);
  for (std::size_t i = 0; i < 4; ++i) s.q[i] /= norm;
  s.r = {70.0, 0.4, -0.3};
  return s;
}

// s moved by h along the motion of u_j: for j = 0..2 a turn of B by h about b_(j+1), e = e (cos h/2,
// sin h/2 b_(j+1)) (a product of quaternions); else q_(j+2) += h (u_j = q_(j+2)').
template <class State>
State moved(State s, std::size_t j, double h) {
  if (j >= 3) {
    s.q[j + 1] += h;
    return s;
  }
  std::array<double, 4> b{std::cos(h / 2), 0.0, 0.0, 0.0};
  b[1 + j] = std::sin(h / 2);
  const std::array<double, 4> a{s.q[0], s.q[1], s.q[2], s.q[3]};
  s.q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  s.q[1] = a[0] * b[1] + b[0] * a[1] + a[2] * b[3] - a[3] * b[2];
  s.q[2] = a[0] * b[2] + b[0] * a[2] + a[3] * b[1] - a[1] * b[3];
  s.q[3] = a[0] * b[3] + b[0] * a[3] + a[1] * b[2] - a[2] * b[1];
  return s;
}
// dx = T dx~: the Euler parameters q_1..4 moved by a turn of B in its axes, de = G(e) dtheta
template <class State>
auto tangent(const State& s) {
  constexpr auto nx = int(State::nq + State::nu);
  Eigen::Matrix<double, nx, nx - 1> t = Eigen::Matrix<double, nx, nx - 1>::Zero();
  t.template topLeftCorner<4, 3>() = kane::detail::attitude_map(s.q[0], s.q[1], s.q[2], s.q[3]);
  t.template bottomRightCorner<nx - 4, nx - 4>().setIdentity();
  return t;
}
// The analytical derivatives of inverse and forward dynamics against central differences of
// kane::inverse_dynamics and kane::forward_dynamics along the motion of each speed (relative errors).
template <class Model>
std::array<double, 4> derivatives_against_differences(const typename Model::state& s, double h = 1e-6) {
  using system = typename Model::system;
  using evaluator = typename Model::evaluator;
  constexpr auto n = int(evaluator::nu);
  evaluator ev;
  ev.update(s);
  const auto id = kane::inverse_dynamics_derivatives<system>(ev);
  const auto fd = kane::forward_dynamics_derivatives<system>(ev);
  Eigen::Matrix<double, n, n> tq, tu, aq, au;
  const auto difference = [&](const auto& p, const auto& m, auto& t, auto& a, std::size_t j) {
    evaluator ep, em;
    ep.update(p), em.update(m);
    const auto c = Eigen::Index(j);
    t.col(c) = (kane::inverse_dynamics<system>(ep).tau - kane::inverse_dynamics<system>(em).tau) / (2 * h);
    a.col(c) = (kane::forward_dynamics<system>(ep).ud - kane::forward_dynamics<system>(em).ud) / (2 * h);
  };
  for (std::size_t j = 0; j < std::size_t(n); ++j) {
    difference(moved(s, j, h), moved(s, j, -h), tq, aq, j);
    auto p = s, m = s;
    p.u[j] += h, m.u[j] -= h;
    difference(p, m, tu, au, j);
  }
  const bool ok = id.status == kane::solve_status::ok && fd.status == kane::solve_status::ok;
  const double bad = ok ? 0.0 : 1.0;
  return {relative(id.dtau_dq, tq) + bad, relative(id.dtau_du, tu) + bad, relative(fd.dud_dq, aq) + bad,
          relative(fd.dud_du, au) + bad};
}
}  // namespace floating_arms
