// kane's model of the n-link chain (chain_dynamics.hpp) as a user writes it: frames turning
// about z, y, x, ..., joints and mass centres along each body's x, full inertias, gravity. The
// evaluator is at level::pose, which the entry points of a system of joint form read (as in
// benchmarks/dynamics6).
#pragma once

#include <kane/kane.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

#include "chain_dynamics.hpp"

namespace chain_model {
using chain_dynamics::L;
using kane::e;
using kane::literal;

template <std::size_t I>  // joint I: z, y, x, z, ...
using axis_of = std::conditional_t<I % 3 == 1, kane::axis::z,
                                   std::conditional_t<I % 3 == 2, kane::axis::y, kane::axis::x>>;
template <std::size_t I>
struct B;
template <>
struct B<0> : kane::root_frame {};
template <std::size_t I>
struct B : kane::frame<B<I - 1>, kane::simple<axis_of<I>, kane::coordinate<I>>> {};

template <std::size_t I>  // joint I
struct J;
template <>
struct J<1> : kane::origin<B<0>> {};
template <std::size_t I>
struct J : kane::point<J<I - 1>, literal(L[I - 2]) * e<B<I - 1>, 1>> {};
template <std::size_t I>  // link I's mass centre
struct C : kane::point<J<I>, literal(L[I - 1] / 2) * e<B<I>, 1>> {};

template <std::size_t I, std::size_t K>  // I11, I22, I33, I12, I23, I31 of link I
inline constexpr literal component = literal(chain_dynamics::inertia[I - 1][K]);
template <std::size_t I>
using link = kane::rigid_body<B<I>, C<I>, literal(chain_dynamics::mass[I - 1]),
                              kane::inertia<B<I>, C<I>, component<I, 0>, component<I, 1>, component<I, 2>,
                                            component<I, 3>, component<I, 4>, component<I, 5>>>;
template <class>
struct links;
template <std::size_t... I>
struct links<std::index_sequence<I...>> {
  using type = kane::system<link<I + 1>..., kane::gravity<literal(-chain_dynamics::g) * e<B<0>, 3>>>;
};

template <std::size_t N>
using system = typename links<std::make_index_sequence<N>>::type;
template <std::size_t N>
using state = kane::state<double, N>;
template <std::size_t N>
using evaluator = kane::evaluator<state<N>, kane::frames<B<N>>, kane::level::pose, kane::qdot_speeds<N>>;
template <std::size_t N>
state<N> state_of(const chain_dynamics::input& in) {
  state<N> s;
  for (std::size_t i = 0; i < N; ++i) s.q[i] = in.q[i], s.u[i] = in.qd[i], s.ud[i] = in.qdd[i];
  return s;
}
}  // namespace chain_model
