// Frame trees shared by the tests.
#pragma once

#include <random>

#include <kane/kane.hpp>

namespace trees {
using q1 = kane::coordinate<1>;
using q2 = kane::coordinate<2>;
using q3 = kane::coordinate<3>;
using q4 = kane::coordinate<4>;
using q5 = kane::coordinate<5>;
using q6 = kane::coordinate<6>;

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, q2>> {};
struct C : kane::frame<B, kane::simple<kane::axis::y, q3>> {};
// A branch beside A: D about the constant axis (1, 2, 2)/3, E by body-fixed 3-1-3.
struct D : kane::frame<N, kane::simple<kane::direction<1, 2, 2>, q4>> {};
struct E : kane::frame<D, kane::body_fixed<3, 1, 3, q5, q6, q1>> {};
// F shares q2 with B: its sin/cos are computed once on a path through both.
struct F : kane::frame<C, kane::space_fixed<1, 2, 3, q2, q5, q6>> {};

// A second root, joined to nothing above.
struct M : kane::root_frame {};
struct G : kane::frame<M, kane::simple<kane::axis::x, q1>> {};

using state6 = kane::state<double, 6>;

inline state6 random_state(std::mt19937& rng, double range = 3.2) {
  std::uniform_real_distribution<double> d(-range, range);
  state6 s;
  for (auto& q : s.q) q = d(rng);
  return s;
}
}  // namespace trees
