#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "trees.hpp"

using namespace trees;
using kane::q;
using kane::u;

namespace {
struct L1 : kane::parameter<1> {};
inline constexpr L1 l1;

// An opaque user function, generic so that kane can run it on dual numbers.
struct softplus {
  template <class T>
  T operator()(T x) const {
    using std::exp, std::log;
    return log(T(1) + exp(x));
  }
};

// Type-level zeros and ones vanish when the expression is built.
static_assert(std::is_same_v<decltype(kane::dt(l1)), kane::zero_t>);
static_assert(std::is_same_v<decltype(kane::dt(q<1>)), kane::coordinate<1, 1>>);
static_assert(std::is_same_v<decltype(kane::dt(kane::dt(q<1>))), kane::coordinate<1, 2>>);
static_assert(std::is_same_v<decltype(kane::dt(u<2>)), kane::speed<2, 1>>);
static_assert(std::is_same_v<decltype(kane::dt(kane::t)), kane::one_t>);
static_assert(std::is_same_v<decltype(kane::dt(l1 * q<1>)), kane::mul<L1, kane::coordinate<1, 1>>>);
static_assert(std::is_same_v<decltype(kane::diff(l1 * q<1> + q<2>, q<3>)), kane::zero_t>);
static_assert(std::is_same_v<decltype(kane::diff(l1 * q<1> + q<2>, q<2>)), kane::one_t>);
static_assert(
    std::is_same_v<decltype(kane::constant<1, 2>{} + kane::constant<1, 3>{}), kane::constant<5, 6>>);
static_assert(std::is_same_v<decltype(-(-q<1>)), kane::coordinate<1>>);
static_assert(std::is_same_v<decltype(kane::e<A, 1> * kane::zero_t{}), kane::zero_vector>);
static_assert(std::is_same_v<decltype(kane::cross(kane::e<A, 1>, kane::e<A, 2>)), kane::unit<A, 3>>);
static_assert(
    std::is_same_v<decltype(kane::cross(kane::e<A, 3>, kane::e<A, 2>)), kane::vneg<kane::unit<A, 1>>>);
static_assert(std::is_same_v<decltype(kane::dot(kane::e<B, 2>, kane::e<B, 2>)), kane::one_t>);
static_assert(std::is_same_v<decltype(kane::dt<A>(kane::e<A, 1>)), kane::zero_vector>);
// Empty nodes: an expression of leaves is an empty object.
static_assert(std::is_empty_v<decltype(l1 * kane::sin(q<1>) * kane::e<B, 1>)>);

template <class X>
concept has_dt = requires(X x) {
  kane::dt(x);
};
// dt(v) of a vector is found and rejected by a static assertion naming the rule (compile_fail).
static_assert(has_dt<decltype(q<1> * q<2>)> && has_dt<decltype(kane::e<A, 1>)> && !has_dt<double>);

template <class X>
double value(const X& x, const state6& s) {
  kane::evaluator<state6, kane::frames<C>> ev;
  ev.update(s);
  return kane::evaluate(x, ev);
}
}  // namespace

TEST_CASE("expr: values and derivatives of sin, cos, sqrt, powers and quotients against closed forms") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-2, 2);
  for (int k = 0; k < 200; ++k) {
    state6 s;
    for (int i = 0; i < 6; ++i) s.q[i] = d(rng), s.qd[i] = d(rng), s.qdd[i] = d(rng);
    const double a = s.q[0], b = s.q[1] + 2.5, ad = s.qd[0], bd = s.qd[1], add = s.qdd[0];
    const auto f = kane::sin(q<1>) * kane::sqrt(q<2> + 2.5) / kane::pow<3>(kane::cos(q<1>) + 2.0);
    const double g = std::cos(a) + 2.0;
    CHECK(value(f, s) == Approx(std::sin(a) * std::sqrt(b) / (g * g * g)).epsilon(1e-14));
    // d/dt by hand: f = u v w with u = sin a, v = sqrt b, w = g^-3
    const double dfdt = std::cos(a) * ad * std::sqrt(b) / (g * g * g) +
                        std::sin(a) * bd / (2 * std::sqrt(b)) / (g * g * g) +
                        std::sin(a) * std::sqrt(b) * 3 * std::sin(a) * ad / (g * g * g * g);
    CHECK(value(kane::dt(f), s) == Approx(dfdt).epsilon(1e-12));
    CHECK(value(kane::diff(f, q<2>), s) ==
          Approx(std::sin(a) / (2 * std::sqrt(b)) / (g * g * g)).epsilon(1e-12));
    // d2/dt2 sin(q1) = -sin q1 q1'^2 + cos q1 q1''
    CHECK(value(kane::dt(kane::dt(kane::sin(q<1>))), s) ==
          Approx(-std::sin(a) * ad * ad + std::cos(a) * add).epsilon(1e-12));
  }
}

TEST_CASE("expr: opaque user functions are differentiated by dual numbers") {
  state6 s;
  s.q[0] = 0.7;
  s.qd[0] = -1.3;
  const auto f = kane::invoke(softplus{}, 2.0 * q<1>);
  const double x = 1.4, sig = 1 / (1 + std::exp(-x));
  CHECK(value(f, s) == Approx(std::log(1 + std::exp(x))).epsilon(1e-15));
  CHECK(value(kane::dt(f), s) == Approx(sig * 2.0 * -1.3).epsilon(1e-14));
  // f'' by nested duals: sigma(1 - sigma) * 4 * q1'^2
  CHECK(value(kane::diff(kane::diff(f, q<1>), q<1>), s) == Approx(sig * (1 - sig) * 4).epsilon(1e-14));
}

TEST_CASE("expr: time, parameters and speeds read the state") {
  kane::state<double, 6, 6, 1> s;
  s.t = 2.0;
  s.p[0] = 0.5;
  s.u[2] = -3.0;
  s.ud[2] = 4.0;
  // u is read by an evaluator with a speed set (here u = q'); without one, reading u does not compile
  kane::evaluator<decltype(s), kane::frames<A>, kane::level::acceleration, kane::qdot_speeds<6>> ev;
  ev.update(s);
  CHECK(kane::evaluate(l1 * kane::t * kane::t + u<3>, ev) == Approx(0.5 * 4 - 3));
  CHECK(kane::evaluate(kane::dt(l1 * kane::t * kane::t + u<3>), ev) == Approx(0.5 * 4 + 4));
  CHECK(kane::evaluate(kane::diff(l1 * kane::t * u<3>, kane::t), ev) == Approx(0.5 * -3));
}

TEST_CASE("expr: expressions built from temporaries are safe in auto variables") {
  // The storage rule: operands by value. Nothing below refers to a dead temporary.
  auto make = [] {
    auto lit = kane::literal(3.0);
    auto x = lit * kane::sin(q<1>) + kane::literal(0.5);
    return x * kane::e<B, 2> + kane::cross(kane::e<A, 1>, 2.0 * kane::e<B, 3>);
  };
  const auto v = make();
  const auto dv = kane::dt<N>(make());
  state6 s;
  s.q = {0.3, -0.4, 0.5, 0, 0, 0};
  s.qd = {1.0, 0.5, 0, 0, 0, 0};
  kane::evaluator<state6, kane::frames<B>> ev;
  ev.update(s);
  const double x = 3.0 * std::sin(0.3) + 0.5;
  const kane::vec<B> vB = kane::express<B>(v, ev);
  const kane::vec<B> a1 = kane::express<B>(kane::e<A, 1>, ev);
  const kane::vec<B> expect = kane::vec<B>(0, x, 0) + kane::cross(a1, kane::vec<B>(0, 0, 2.0));
  CHECK(kane::is_approx(vB, expect, 1e-14));
  CHECK(std::isfinite(kane::express<N>(dv, ev)[0]));
}
