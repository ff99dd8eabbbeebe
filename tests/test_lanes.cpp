// kane::lanes as the scalar of kane::motion: W states in one call, lane by lane equal to the scalar
// path, with every lane's own status (good, singular and non-finite states mixed in one batch),
// and a batch that is not a multiple of W.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include <kane/kane.hpp>
#include <kane/scalars/lanes.hpp>

#include "../examples/models/arm6_dynamics.hpp"
#include "../examples/models/bicycle.hpp"
#include "../examples/models/disc.hpp"
#include "../examples/models/gyrostat.hpp"
#include "../examples/models/heavy_top.hpp"
#include "../examples/models/pendulum_absolute.hpp"

namespace {

// x' of count states by the scalar motion Scalar and by lanes of W (Lanes), compared lane by lane:
// equal statuses, NaN where not ok, |lane - scalar| <= tol (1 + |scalar|) where ok.
template <class Scalar, class Lanes, class S, std::size_t N>
void compare(Scalar& one, Lanes& many, const std::vector<std::array<S, N>>& xs, S tol) {
  using L = typename Lanes::scalar;
  constexpr std::size_t W = L::width;
  for (std::size_t first = 0; first < xs.size(); first += W) {
    const std::size_t count = xs.size() - first < W ? xs.size() - first : W;
    const auto x = kane::to_lanes<W>(&xs[first], count);
    std::array<L, N> xd;
    many(x, xd, L(S(0)));
    std::vector<std::array<S, N>> out(W);
    kane::from_lanes(xd, out.data(), count);
    const auto statuses = many.status();
    for (std::size_t l = 0; l < count; ++l) {
      std::array<S, N> xd1;
      one(xs[first + l], xd1, S(0));
      INFO("state " << first + l << ": scalar " << kane::to_string(one.status()) << ", lane "
                    << kane::to_string(statuses[l]));
      CHECK(statuses[l] == one.status());
      for (std::size_t k = 0; k < N; ++k) {
        if (one.status() == kane::solve_status::ok)
          CHECK(std::abs(out[l][k] - xd1[k]) <= tol * (1 + std::abs(xd1[k])));
        else
          CHECK(std::isnan(out[l][k]));
      }
    }
    for (std::size_t l = count; l < W; ++l)  // the padding repeats the batch's first state
      CHECK(statuses[l] == statuses[0]);
  }
}
// The same with both right-hand sides built at default states (no parameters).
template <class Scalar, class Lanes, class S, std::size_t N>
void compare(const std::vector<std::array<S, N>>& xs, S tol) {
  Scalar one{typename Scalar::state_type{}};
  Lanes many{typename Lanes::state_type{}};
  compare(one, many, xs, tol);
}

// count random states of N numbers in [-2, 2].
template <class S, std::size_t N>
std::vector<std::array<S, N>> states(std::size_t count, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> d(-2, 2);
  std::vector<std::array<S, N>> xs(count);
  for (auto& x : xs)
    for (auto& v : x) v = S(d(g));
  return xs;
}

template <class S, std::size_t W>
using lanes_motion_top =
    kane::motion<models::heavy_top::system, models::heavy_top::speeds, kane::lanes<S, W>>;
template <class S>
using scalar_motion_top = kane::motion<models::heavy_top::system, models::heavy_top::speeds, S>;

}  // namespace

TEST_CASE("lanes: arithmetic, comparisons and functions act lane by lane", "[lanes]") {
  using L = kane::lanes<double, 8>;
  L a, b;
  for (std::size_t i = 0; i < 8; ++i) a.set(i, 0.3 * double(i) - 1.1), b.set(i, 1.7 - 0.2 * double(i));
  const L s = a * b + a / b - b, c = sin(a), k = cos(b), r = sqrt(abs(a)), t = atan2(a, b);
  const auto less = a < b;
  const L m = select(less, a, b);
  for (std::size_t i = 0; i < 8; ++i) {
    const double x = a[i], y = b[i];
    CHECK(s[i] == x * y + x / y - y);
    CHECK(std::abs(c[i] - std::sin(x)) <= 4e-16);
    CHECK(std::abs(k[i] - std::cos(y)) <= 4e-16);
    CHECK(r[i] == std::sqrt(std::abs(x)));
    CHECK(t[i] == Approx(std::atan2(x, y)).epsilon(1e-15));
    CHECK(less[i] == (x < y));
    CHECK(m[i] == (x < y ? x : y));
  }
  CHECK(any_of(less));
  CHECK_FALSE(all_of(less));
  CHECK(all_of(a == a));
}

TEST_CASE(
    "lanes: sine and cosine in vector registers within an ulp or two, large and non-finite lane by lane",
    "[lanes]") {
  using L = kane::lanes<double, 8>;
  std::mt19937 g(3);
  double worst = 0;
  for (double scale : {1.0, 100.0, 1e5}) {
    std::uniform_real_distribution<double> d(-scale, scale);
    for (int n = 0; n < 2000; ++n) {
      const L x = L::generate([&](std::size_t) { return d(g); });
      const L s = sin(x), c = cos(x);
      for (std::size_t i = 0; i < 8; ++i)
        worst = std::max({worst, std::abs(s[i] - std::sin(x[i])), std::abs(c[i] - std::cos(x[i]))});
    }
  }
  CHECK(worst <= 4e-16);
  const double odd[8] = {1e6,
                         -3e300,
                         std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN(),
                         -0.0,
                         1e-310,
                         0.5,
                         -2.5};
  const L x = L::generate([&](std::size_t i) { return odd[i]; });
  const L s = sin(x), c = cos(x);
  for (std::size_t i = 0; i < 8; ++i) {
    INFO("x = " << odd[i]);
    if (std::isnan(std::sin(odd[i]))) {
      CHECK(std::isnan(s[i]));
      CHECK(std::isnan(c[i]));
    } else {
      CHECK(std::abs(s[i] - std::sin(odd[i])) <= 4e-16);
      CHECK(std::abs(c[i] - std::cos(odd[i])) <= 4e-16);
    }
  }
  CHECK(std::signbit(s[4]));         // sin(-0) = -0
  using F = kane::lanes<float, 16>;  // floats: within two ulps of std::sin and std::cos in float
  float fworst = 0;
  std::uniform_real_distribution<float> f(-8192, 8192);
  for (int n = 0; n < 2000; ++n) {
    const F y = F::generate([&](std::size_t i) { return i < 8 ? f(g) / 4096 : f(g); });
    const F sf = sin(y), cf = cos(y);
    for (std::size_t i = 0; i < 16; ++i)
      fworst = std::max({fworst, std::abs(sf[i] - std::sin(y[i])), std::abs(cf[i] - std::cos(y[i]))});
  }
  CHECK(fworst <= 2.5e-7f);
}

TEST_CASE("lanes: to_lanes pads a short batch with its first state, from_lanes writes count states",
          "[lanes]") {
  std::vector<std::array<double, 3>> xs{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  const auto x = kane::to_lanes<4>(xs.data(), 3);
  CHECK(x[0][0] == 1);
  CHECK(x[2][1] == 6);
  CHECK(x[1][3] == 2);  // lane 3: the first state again
  std::array<std::array<double, 3>, 4> back{};
  kane::from_lanes(x, back.data(), 3);
  CHECK(back[2] == xs[2]);
  CHECK(back[3] == std::array<double, 3>{0, 0, 0});  // not written
}

TEST_CASE("lanes: the heavy top's motion, lane by lane as the scalar path, statuses per lane", "[lanes]") {
  auto xs = states<double, 6>(21, 7);  // 21 = 2 * 8 + 5: the last batch short
  xs[2][1] = 0;                        // q2 = 0: the body rates do not define q' (singular)
  xs[5][4] = std::numeric_limits<double>::quiet_NaN();
  xs[9][0] = std::numeric_limits<double>::infinity();
  xs[17][1] = 0;  // a singular lane in the short batch
  compare<scalar_motion_top<double>, lanes_motion_top<double, 8>>(xs, 1e-13);
  compare<scalar_motion_top<double>, lanes_motion_top<double, 4>>(xs, 1e-13);
  auto fs = states<float, 6>(21, 8);
  fs[3][1] = 0;
  fs[12][5] = std::numeric_limits<float>::quiet_NaN();
  compare<scalar_motion_top<float>, lanes_motion_top<float, 16>>(fs, 1e-5f);
}

TEST_CASE("lanes: the spacecraft on Euler parameters, lane by lane as the scalar path", "[lanes]") {
  namespace m = models::gyrostat;
  auto xs = states<double, 14>(19, 11);
  xs[4][0] = xs[4][1] = xs[4][2] = xs[4][3] = 0;  // no attitude: the parameters' norm is 0
  xs[7][10] = std::numeric_limits<double>::quiet_NaN();
  compare<kane::motion<m::system, m::speeds>, kane::motion<m::system, m::speeds, kane::lanes<double, 8>>>(
      xs, 1e-13);
}

TEST_CASE("lanes: the double pendulum on absolute angles (u = q'), lane by lane as the scalar path",
          "[lanes]") {
  auto xs = states<double, 4>(13, 5);
  xs[6][3] = std::numeric_limits<double>::infinity();
  using system = models::pendulum_absolute::system;
  compare<kane::motion<system>, kane::motion<system, void, kane::lanes<double, 8>>>(xs, 1e-13);
}

TEST_CASE("lanes: the rolling disc's constrained motion, lane by lane as the scalar path", "[lanes]") {
  namespace d = models::disc;
  using L = kane::lanes<double, 8>;
  kane::state_of<d::system, d::rolling::speed_set> s;
  s.p = {0.3, 2.0, 9.81};  // r, m, g
  kane::state_of<d::system, d::rolling::speed_set, L> ls;
  ls.p = {L(0.3), L(2.0), L(9.81)};
  kane::constrained_motion<d::system, d::rolling> one(s);
  kane::constrained_motion<d::system, d::rolling, L> many(ls);
  auto xs = states<double, 8>(11, 13);
  xs[3][4] = std::numeric_limits<double>::quiet_NaN();
  xs[9][1] = std::numeric_limits<double>::infinity();
  compare(one, many, xs, 1e-13);
}

TEST_CASE("lanes: the 6R arm's forward and inverse dynamics on the recursive path, lane by lane", "[lanes]") {
  namespace a = models::arm6;
  using L = kane::lanes<double, 8>;
  using state = kane::state<double, 6>;
  using lstate = kane::state<L, 6>;
  using frames = kane::frames<a::B6>;
  using evaluator = kane::evaluator<state, frames, kane::level::pose, kane::qdot_speeds<6>>;
  using levaluator = kane::evaluator<lstate, frames, kane::level::pose, kane::qdot_speeds<6>>;
  const auto xs = states<double, 18>(8, 17);  // q, u, u'
  lstate ls;
  for (std::size_t k = 0; k < 6; ++k) {
    ls.q[k] = L::generate([&](std::size_t l) { return xs[l][k]; });
    ls.u[k] = L::generate([&](std::size_t l) { return xs[l][6 + k]; });
    ls.ud[k] = L::generate([&](std::size_t l) { return xs[l][12 + k]; });
  }
  ls.q[2].set(5, std::numeric_limits<double>::quiet_NaN());
  levaluator lev;
  lev.update(ls);
  const auto lf = kane::forward_dynamics<a::links>(lev);
  const auto li = kane::inverse_dynamics<a::links>(lev);
  const auto le = kane::mass_matrix_and_forcing<a::links>(lev);
  for (std::size_t l = 0; l < 8; ++l) {
    state s;
    for (std::size_t k = 0; k < 6; ++k) s.q[k] = ls.q[k][l], s.u[k] = ls.u[k][l], s.ud[k] = ls.ud[k][l];
    evaluator ev;
    ev.update(s);
    const auto f = kane::forward_dynamics<a::links>(ev);
    const auto i = kane::inverse_dynamics<a::links>(ev);
    const auto e = kane::mass_matrix_and_forcing<a::links>(ev);
    INFO("lane " << l);
    CHECK(lf.status[l] == f.status);
    CHECK(li.status[l] == i.status);
    CHECK(le.status[l] == e.status);
    CHECK((l == 5) == (f.status == kane::solve_status::not_finite));
    for (int k = 0; k < 6; ++k) {
      if (f.status == kane::solve_status::ok) {
        CHECK(std::abs(lf.ud(k)[l] - f.ud(k)) <= 1e-13 * (1 + std::abs(f.ud(k))));
        CHECK(std::abs(li.tau(k)[l] - i.tau(k)) <= 1e-13 * (1 + std::abs(i.tau(k))));
        CHECK(std::abs(le.f(k)[l] - e.f(k)) <= 1e-13 * (1 + std::abs(e.f(k))));
        for (int j = 0; j < 6; ++j)
          CHECK(std::abs(le.M(k, j)[l] - e.M(k, j)) <= 1e-13 * (1 + std::abs(e.M(k, j))));
      } else {
        CHECK(std::isnan(lf.ud(k)[l]));
        CHECK(std::isnan(li.tau(k)[l]));
      }
    }
  }
}

TEST_CASE("lanes: the Whipple bicycle's constrained motion, lane by lane as the scalar path", "[lanes]") {
  namespace b = models::bicycle;
  using L = kane::lanes<double, 8>;
  using lstate = kane::state<L, 6, 8, 27>;
  using levaluator =
      kane::evaluator<lstate, kane::frames<b::Wr, b::Wf>, kane::level::acceleration, b::speeds>;
  const b::dynamics_state s = b::benchmark_parameters();
  lstate ls;
  for (std::size_t i = 0; i < 27; ++i) ls.p[i] = L(s.p[i]);
  kane::constrained_motion<b::system, b::rolling, b::dynamics_evaluator> one(s);
  kane::constrained_motion<b::system, b::rolling, levaluator> many(ls);
  auto xs = states<double, 9>(10, 19);
  for (auto& x : xs) x[4] = 0.1 * x[4];  // pitch near its value on flat ground
  xs[2][8] = std::numeric_limits<double>::quiet_NaN();
  compare(one, many, xs, 1e-12);
}
