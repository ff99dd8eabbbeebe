#include <catch2/catch.hpp>

#include <type_traits>

#include "trees.hpp"

using namespace trees;
using kane::detail::list;
using kane::detail::path;

namespace {
template <class P, class Up, class Down, class Common>
constexpr bool path_is = std::is_same_v<typename P::up, Up>&& std::is_same_v<typename P::down, Down>&&
    std::is_same_v<typename P::common, Common>;

static_assert(kane::Frame<N> && kane::Frame<A> && kane::Frame<E>);
static_assert(!kane::Frame<int> && !kane::Frame<kane::vec<N>>);
static_assert(path_is<path<N, C>, list<>, list<A, B, C>, N>);
static_assert(path_is<path<C, N>, list<C, B, A>, list<>, N>);
// Rotation sequences add two auxiliary frames each.
using E1 = kane::detail::aux_frame<D, E::orientation::steps, 1>;
using E2 = kane::detail::aux_frame<D, E::orientation::steps, 2>;
using F2 = kane::detail::aux_frame<C, F::orientation::steps, 2>;
static_assert(std::is_same_v<E::tree_parent, E2> && std::is_same_v<E2::tree_parent, E1>);
static_assert(std::is_same_v<E1::step, kane::simple<kane::axis::z, q5>>);
static_assert(path_is<path<C, E>, list<C, B, A>, list<D, E1, E2, E>, N>);
static_assert(
    path_is<path<F, B>, list<F, F2, kane::detail::aux_frame<C, F::orientation::steps, 1>, C>, list<>, B>);
static_assert(std::is_same_v<kane::detail::closure<C, A, E>::type, list<N, A, B, C, D, E1, E2, E>>);
static_assert(std::is_same_v<kane::detail::root_of<E>, N> && std::is_same_v<kane::detail::root_of<G>, M>);
static_assert(path_is<path<B, B>, list<>, list<>, B>);
static_assert(!path<C, G>::joined && path<G, M>::joined);
// Coordinates on a path, each once: F's space-fixed sequence reuses q2.
static_assert(kane::detail::unique_indices<3, 1, 3, 2>() == std::array<std::size_t, 3>{1, 2, 3});
}  // namespace

TEST_CASE("state: plain, zero-initialised, indexed by coordinate") {
  using S = kane::state<double, 3, 2, 1>;
  static_assert(std::is_trivially_copyable_v<S> && std::is_aggregate_v<S>);
  static_assert(sizeof(S) == (3 * 3 + 2 * 2 + 1 + 1) * sizeof(double));
  static_assert(S::nq == 3 && S::nu == 2 && S::np == 1);
  S s;
  CHECK(s.q == std::array<double, 3>{0, 0, 0});
  CHECK(s.t == 0.0);
  s[kane::q<2>] = 0.75;
  CHECK(s.q[1] == 0.75);
  const S& cs = s;
  CHECK(cs[kane::q<2>] == 0.75);
}
