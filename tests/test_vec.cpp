#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "trees.hpp"

using namespace trees;
using kane::vec;

namespace {
template <class L, class R>
concept addable = requires(L l, R r) {
  l + r;
};
template <class L, class R>
concept subtractable = requires(L l, R r) {
  l - r;
};
template <class L, class R>
concept dottable = requires(L l, R r) {
  kane::dot(l, r);
};
template <class L, class R>
concept crossable = requires(L l, R r) {
  kane::cross(l, r);
};
template <class L, class R>
concept comparable = requires(L l, R r) {
  l == r;
};
template <class L, class R>
concept scalable = requires(L l, R r) {
  l* r;
};

// Mixing frames is rejected by a static assertion that names the rule and the frames (the
// operators exist for every pair, so that the first error line is kane's; compile_fail/vec_frames).
static_assert(addable<vec<A>, vec<A>> && subtractable<vec<B>, vec<B>> && dottable<vec<A>, vec<A>>);
static_assert(crossable<vec<A>, vec<A>> && comparable<vec<A>, vec<A>> &&
              std::is_assignable_v<vec<A>&, vec<A>>);
// Foreign types never match kane's operators.
static_assert(scalable<double, vec<A>> && scalable<vec<A>, int> && !scalable<vec<A>, vec<A>>);
static_assert(!addable<vec<A>, Eigen::Vector3d> && !addable<vec<A>, double>);
static_assert(std::is_trivially_copyable_v<vec<A>> && sizeof(vec<A>) == 3 * sizeof(double));
static_assert(sizeof(vec<A, float>) == 3 * sizeof(float));
}  // namespace

TEST_CASE("vec: components, arithmetic and equality within one frame") {
  const vec<A> p(1.0, -2.0, 0.5), r(0.25, 4.0, -3.0);
  CHECK(vec<A>() == vec<A>(0, 0, 0));
  CHECK(p[0] == 1.0);
  CHECK(p[1] == -2.0);
  CHECK(p[2] == 0.5);
  CHECK(p + r == vec<A>(1.25, 2.0, -2.5));
  CHECK(p - r == vec<A>(0.75, -6.0, 3.5));
  CHECK(-p == vec<A>(-1.0, 2.0, -0.5));
  CHECK(2 * p == vec<A>(2.0, -4.0, 1.0));
  CHECK(p * 0.5 == vec<A>(0.5, -1.0, 0.25));
  CHECK(p / 4 == vec<A>(0.25, -0.5, 0.125));
  CHECK(p != r);
  vec<A> s = p;
  s += r;
  s -= p;
  CHECK(s == r);
  s *= 2.0;
  s /= 4.0;
  CHECK(s == 0.5 * r);
}

TEST_CASE("vec: dot, cross and norm against closed forms") {
  const vec<B> p(1.0, -2.0, 0.5), r(0.25, 4.0, -3.0);
  CHECK(kane::dot(p, r) == Approx(1.0 * 0.25 - 2.0 * 4.0 - 0.5 * 3.0).epsilon(1e-15));
  // p x r = (p2 r3 - p3 r2, p3 r1 - p1 r3, p1 r2 - p2 r1)
  CHECK(kane::cross(p, r) ==
        vec<B>(-2.0 * -3.0 - 0.5 * 4.0, 0.5 * 0.25 - 1.0 * -3.0, 1.0 * 4.0 - -2.0 * 0.25));
  CHECK(kane::cross(vec<B>::e1(), vec<B>::e2()) == vec<B>::e3());
  CHECK(kane::cross(vec<B>::e2(), vec<B>::e3()) == vec<B>::e1());
  CHECK(kane::cross(vec<B>::e3(), vec<B>::e1()) == vec<B>::e2());
  CHECK(kane::norm(vec<B>(2.0, 3.0, 6.0)) == 7.0);
  CHECK(kane::dot(kane::cross(p, r), p) == Approx(0.0).margin(1e-15));
}

TEST_CASE("vec: is_approx compares componentwise and rejects NaN") {
  const vec<C> p(1.0, 2.0, 3.0);
  CHECK(kane::is_approx(p, vec<C>(1.0 + 1e-13, 2.0, 3.0 - 1e-13), 1e-12));
  CHECK_FALSE(kane::is_approx(p, vec<C>(1.0, 2.0 + 1e-9, 3.0), 1e-12));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(kane::is_approx(p, vec<C>(nan, 2.0, 3.0), 1e-12));
  CHECK_FALSE(vec<C>(nan, 2.0, 3.0) == vec<C>(nan, 2.0, 3.0));
}

TEST_CASE("vec: Eigen interop views without copying") {
  vec<N> p(1.0, 2.0, 3.0);
  auto view = p.eigen();
  CHECK(static_cast<const void*>(view.data()) == static_cast<const void*>(&p));
  view.z() = 9.0;
  CHECK(p[2] == 9.0);
  const Eigen::Vector3d e(0.5, -1.5, 2.5);
  const vec<N> from(e + Eigen::Vector3d::Ones());
  CHECK(from == vec<N>(1.5, -0.5, 3.5));
  // On a temporary, eigen() copies: no view outlives its vector.
  static_assert(std::is_same_v<decltype(vec<N>(1, 2, 3).eigen()), Eigen::Vector3d>);
  static_assert(std::is_same_v<decltype(kane::dcm<N, A>().eigen()), Eigen::Matrix3d>);
  const vec<N, float> pf(1.0f, 2.0f, 3.0f);
  CHECK(kane::norm(pf) == Approx(std::sqrt(14.0f)));
}
