// Models of the recursive dynamics' tests: a tree with two branches from N, a fixed tool rotation,
// an oblique axis, a particle, a force and torques; and random states.
#pragma once

#include <random>

#include <kane/kane.hpp>

namespace recursive {
using kane::e;
using kane::literal;

// A tree: two branches from N, a fixed tool rotation, a particle, a force and torques.
namespace tree {
using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
using q3 = kane::coordinate<3>;
using q4 = kane::coordinate<4>;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::y, q2>> {};
struct T : kane::frame<B, kane::simple<kane::axis::x, kane::constant<1, 3>>> {};  // a tool, fixed in B
struct C : kane::frame<N, kane::simple<kane::axis::x, q3>> {};
struct D : kane::frame<C, kane::simple<kane::direction<1, 1, 0>, q4>> {};  // an oblique axis
struct O : kane::origin<N> {};
struct Ao : kane::point<O, 0.2 * e<A, 1> + 0.1 * e<A, 3>> {};
struct JB : kane::point<O, 0.4 * e<A, 1>> {};
struct Bo : kane::point<JB, 0.15 * e<B, 1> - 0.05 * e<B, 2>> {};
struct To : kane::point<JB, 0.3 * e<T, 1> + 0.02 * e<T, 3>> {};
struct JC : kane::point<O, -0.3 * e<N, 2>> {};
struct P : kane::point<JC, 0.25 * e<C, 3>> {};
struct Do : kane::point<P, 0.1 * e<D, 2>> {};
using system = kane::system<
    kane::rigid_body<A, Ao, literal(1.5), kane::inertia<A, Ao, literal(0.03), literal(0.02), literal(0.04)>>,
    kane::rigid_body<B, Bo, literal(1.1),
                     kane::inertia<B, Bo, literal(0.01), literal(0.015), literal(0.012), literal(0.001)>>,
    kane::rigid_body<T, To, literal(0.4),
                     kane::inertia<T, To, literal(0.004), literal(0.003), literal(0.005), literal(0.0),
                                   literal(0.0005), literal(-0.0002)>>,
    kane::particle<P, literal(0.7)>,
    kane::rigid_body<D, Do, literal(0.9),
                     kane::inertia<D, Do, literal(0.02), literal(0.01), literal(0.025), literal(0.002)>>,
    kane::force<To, kane::q<2> * e<N, 1> + 2.0 * e<B, 3>>, kane::torque<C, -0.3 * kane::u<3> * e<C, 1>>,
    kane::torque<D, 0.5 * e<D, 3>>, kane::gravity<literal(-9.81) * e<N, 3>>>;
using state = kane::state<double, 4>;
using evaluator = kane::evaluator<state, kane::frames<T, D>, kane::level::acceleration, kane::qdot_speeds<4>>;
}  // namespace tree

// q, u and u' drawn from [-2, 2]
template <class St>
St random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  St s;
  for (auto& x : s.q) x = d(rng);
  for (auto& x : s.u) x = d(rng);
  for (auto& x : s.ud) x = d(rng);
  return s;
}
}  // namespace recursive
