// kane::lanes: the arithmetic, sine and cosine, loading and storing, and kane::motion over lanes,
// W states in one call, lane by lane equal to the scalar path, with every lane's own status (good,
// singular and non-finite states mixed in one batch), and a batch that is not a multiple of W.
// Both builds: g++'s and Clang's vector types. The constrained and recursive entry points:
// test_lane_models.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../examples/models/gyrostat.hpp"
#include "../examples/models/heavy_top.hpp"
#include "../examples/models/pendulum_absolute.hpp"
#include "lanes_compare.hpp"

namespace {
using lanes_test::compare;
using lanes_test::states;

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

TEST_CASE(
    "numbers: an evaluator's sines and cosines of its angles are those of kane::lanes, an ulp or two "
    "from std::sin and std::cos",
    "[lanes]") {
  namespace m = models::pendulum_absolute;
  using L = kane::lanes<double, 8>;
  kane::evaluator<kane::state<double, 2>, kane::frames<m::A, m::B>> ev;
  std::mt19937 g(5);
  std::uniform_real_distribution<double> d(-1e5, 1e5);
  const double odd[] = {-0.0, 0.0, 1e-310, 0.5, -2.5, 1e6, -3e300, std::numeric_limits<double>::infinity()};
  for (int n = 0; n < 4000; ++n) {
    kane::state<double, 2> s;
    s.q = {n < 8 ? odd[n] : d(g) / (n % 2 ? 1e4 : 1.0), d(g)};
    ev.update(s);
    const double* a = ev.axes<m::A>().data();  // e_A1 = (cos q1, sin q1, 0) in N
    const L lanes_s = sin(L(s.q[0])), lanes_c = cos(L(s.q[0]));
    INFO("q1 = " << s.q[0]);
    if (!std::isfinite(s.q[0])) {
      CHECK(std::isnan(a[0]));
      continue;
    }
    CHECK(std::abs(a[0] - std::cos(s.q[0])) <= 4e-16);
    CHECK(std::abs(a[1] - std::sin(s.q[0])) <= 4e-16);
    CHECK(std::signbit(a[1]) == std::signbit(std::sin(s.q[0])));
#if defined(__SSE2__) && defined(__GNUC__)
    CHECK((a[0] == lanes_c[0] && a[1] == lanes_s[0]));  // one kernel for numbers and lanes
#endif
  }
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

namespace {
// to_lanes and from_lanes of count states of N numbers against lane l = state l, number by number
template <class S, std::size_t W, std::size_t N>
void check_transposes(std::size_t count) {
  std::vector<std::array<S, N>> xs(W);
  for (std::size_t l = 0; l < W; ++l)
    for (std::size_t k = 0; k < N; ++k) xs[l][k] = S(100 * l + k);
  const auto x = kane::to_lanes<W>(xs.data(), count);
  std::vector<std::array<S, N>> back(W);
  for (auto& b : back) b.fill(S(-1));
  kane::from_lanes(x, back.data(), count);
  for (std::size_t l = 0; l < W; ++l) {
    INFO("W " << W << ", N " << N << ", count " << count << ", lane " << l);
    for (std::size_t k = 0; k < N; ++k) {
      CHECK(x[k][l] == xs[l < count ? l : 0][k]);
      CHECK(back[l][k] == (l < count ? xs[l][k] : S(-1)));
    }
  }
}
}  // namespace

TEST_CASE("lanes: to_lanes and from_lanes of states shorter and longer than the lanes", "[lanes]") {
  check_transposes<double, 2, 5>(2);
  check_transposes<double, 4, 3>(4);  // fewer numbers than lanes
  check_transposes<double, 4, 6>(4);
  check_transposes<double, 4, 8>(4);
  check_transposes<double, 4, 8>(3);   // a short batch
  check_transposes<double, 8, 14>(8);  // the spacecraft's state
  check_transposes<float, 16, 20>(16);
  check_transposes<float, 8, 8>(8);
}

TEST_CASE("lanes: to_lanes and from_lanes through row functions, states inside the user's structs",
          "[lanes]") {
  struct in {
    int id;
    std::array<double, 6> x;
  };
  struct out {
    double xd[6];
    int status;
  };
  std::vector<in> ins(5);
  for (std::size_t l = 0; l < ins.size(); ++l) {
    ins[l].id = int(l);
    for (std::size_t k = 0; k < 6; ++k) ins[l].x[k] = double(10 * l + k);
  }
  const auto x = kane::to_lanes<4, 6>([&](std::size_t l) { return ins[1 + l].x.data(); }, 3);
  for (std::size_t l = 0; l < 4; ++l)
    for (std::size_t k = 0; k < 6; ++k) CHECK(x[k][l] == ins[l < 3 ? 1 + l : 1].x[k]);
  std::vector<out> outs(4, out{{-1, -1, -1, -1, -1, -1}, 7});
  kane::from_lanes(
      x, [&](std::size_t l) { return outs[l].xd; }, 3);
  for (std::size_t l = 0; l < 4; ++l) {
    for (std::size_t k = 0; k < 6; ++k) CHECK(outs[l].xd[k] == (l < 3 ? ins[1 + l].x[k] : -1.0));
    CHECK(outs[l].status == 7);  // the numbers after xd untouched
  }
}

TEST_CASE("lanes: load and store W numbers of a structure-of-arrays buffer", "[lanes]") {
  using L = kane::lanes<double, 4>;
  std::array<std::array<double, 9>, 2> soa{};  // two quantities of 9 states: lanes at an odd offset
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t l = 0; l < 9; ++l) soa[k][l] = double(100 * k + l);
  const L a = L::load(soa[0].data() + 1), b = L::load(soa[1].data() + 5);
  for (std::size_t l = 0; l < 4; ++l) {
    CHECK(a[l] == double(1 + l));
    CHECK(b[l] == double(105 + l));
  }
  std::array<double, 6> out{-1, -1, -1, -1, -1, -1};
  (a + b).store(out.data() + 1);
  CHECK(out[0] == -1);
  for (std::size_t l = 0; l < 4; ++l) CHECK(out[1 + l] == double(106 + 2 * l));
  CHECK(out[5] == -1);
}

namespace {
// all_of and any_of of masks with each one lane differing from the rest
template <class S, std::size_t W>
void check_reductions() {
  using L = kane::lanes<S, W>;
  const L zero(0), one(1);
  CHECK(all_of(one > zero));
  CHECK(any_of(one > zero));
  CHECK(!all_of(one < zero));
  CHECK(!any_of(one < zero));
  for (std::size_t i = 0; i < W; ++i) {
    L a = zero;
    a.set(i, S(1));
    INFO("W " << W << ", lane " << i);
    CHECK(any_of(a > zero));
    CHECK(!all_of(a > zero));
    CHECK(any_of(a == zero) == (W > 1));
    CHECK(!all_of(a == zero));
  }
}
}  // namespace

TEST_CASE("lanes: all_of and any_of see every lane", "[lanes]") {
  check_reductions<double, 2>();
  check_reductions<double, 4>();
  check_reductions<double, 8>();
  check_reductions<float, 4>();
  check_reductions<float, 8>();
  check_reductions<float, 16>();
}

namespace {
// A coupled block of N unknowns in 8 lanes: each lane against detail::invert of its own matrix, with
// pivots in other places per lane, an exactly singular lane, a NaN and an inf lane
template <int N>
void check_block_inverse() {
  using L = kane::lanes<double, 8>;
  Eigen::Matrix<L, N, N> m, inv;
  std::array<Eigen::Matrix<double, N, N>, 8> ms;
  for (std::size_t l = 0; l < 8; ++l) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        ms[l](i, j) = std::sin(1.0 + double(l) + 3.1 * i + 1.7 * j * j) * (i == int((l + j) % N) ? 9.0 : 1.0);
    if (l == 3) ms[l].row(N - 1) = 2.0 * ms[l].row(0) - ms[l].row(1);  // singular
    if (l == 5) ms[l](1, N - 1) = std::numeric_limits<double>::quiet_NaN();
    if (l == 6) ms[l](N - 1, 0) = std::numeric_limits<double>::infinity();
  }
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m(i, j) = L::generate([&](std::size_t l) { return ms[l](i, j); });
  const auto ok = factor_block(m, inv, L(-1.0));
  for (std::size_t l = 0; l < 8; ++l) {
    INFO("N " << N << ", lane " << l);
    Eigen::Matrix<double, N, N> one;
    const bool expected = kane::detail::invert(ms[l], one);
    CHECK(ok[l] == expected);
    CHECK(expected == (l != 3 && l != 5 && l != 6));
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        if (!expected)
          CHECK(std::isnan(inv(i, j)[l]));
        else
          CHECK(std::abs(inv(i, j)[l] - one(i, j)) <= 1e-13 * (1 + std::abs(one(i, j))));
      }
  }
}
}  // namespace

TEST_CASE("lanes: a coupled block inverted in every lane at once as one state alone", "[lanes]") {
  check_block_inverse<3>();
  check_block_inverse<4>();
  check_block_inverse<5>();
}

TEST_CASE("lanes: the exact powers of two that scale a solve, lane by lane as for one number", "[lanes]") {
  using L = kane::lanes<double, 8>;
  const double tiny = std::numeric_limits<double>::denorm_min(), big = std::numeric_limits<double>::max();
  const std::array<std::array<double, 8>, 2> xs{
      {{1.0, 3.0, 0.75, 1e-310, tiny, 1e300, big, 0x1p-1022},
       {0x1p-1023, 0x1.8p-1023, 2.0, 0.5, 7e-5, 1e-200, 1e200, 0x1p1023}}};
  for (const auto& x : xs) {
    const L r = kane::detail::inverse_power_of_two(L::generate([&](std::size_t l) { return x[l]; }));
    for (std::size_t l = 0; l < 8; ++l) {
      INFO("x = " << x[l]);
      CHECK(r[l] == kane::detail::inverse_power_of_two(x[l]));
      int e = 0;
      std::frexp(x[l], &e);  // 2^(e-1) <= x < 2^e, e clamped so that 2^-e is normal
      CHECK(r[l] == std::ldexp(1.0, -std::clamp(e, std::numeric_limits<double>::min_exponent - 2,
                                                std::numeric_limits<double>::max_exponent - 2)));
    }
  }
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
  // the same states from and to structure-of-arrays buffers (kane::soa_block), 4 lanes
  kane::motion<m::system, m::speeds> one{kane::state_of<m::system, m::speeds>{}};
  kane::motion<m::system, m::speeds, kane::lanes<double, 4>> many{
      kane::state_of<m::system, m::speeds, kane::lanes<double, 4>>{}};
  lanes_test::compare_soa(one, many, xs, 1e-13);
}

TEST_CASE("lanes: the double pendulum on absolute angles (u = q'), lane by lane as the scalar path",
          "[lanes]") {
  auto xs = states<double, 4>(13, 5);
  xs[6][3] = std::numeric_limits<double>::infinity();
  using system = models::pendulum_absolute::system;
  compare<kane::motion<system>, kane::motion<system, void, kane::lanes<double, 8>>>(xs, 1e-13);
}
