// A Monte Carlo of the rolling disc (models/disc.hpp): random initial lean, lean rate and rolling
// speed, each start integrated 3 s by RK4 (dt = 2 ms) through kane::constrained_motion. A start stays
// upright if |lean| stays below 1 rad. The fraction that stays upright, by speed, is printed and, with a
// path ("-": none), plotted as SVG. W starts go through one call as kane::lanes<double, W>, W as wide as
// the target's vector registers (kane::native_lanes<double>), each lane with its own stop: a disc that
// falls stops counting, the others roll on. W = 1 is the scalar path (the default without AVX).
// The batches are split across OpenMP threads (g++ -fopenmp), one right-hand side per thread; without
// OpenMP they run in one thread with the same results. A progress line goes to stderr.
//
//   example_disc_monte_carlo [starts] [plot.svg] [W: 1, or more for the register's lanes]
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string_view>
#include <vector>

#include <kane/scalars/lanes.hpp>

#include "models/disc.hpp"
#include "rk4.hpp"

namespace d = models::disc;
template <class S>
using rhs = kane::constrained_motion<d::system, d::rolling, S>;  // x: yaw, lean, spin, x, y, u1, u2, u3

constexpr double radius = 0.3, top_speed = 3.6;  // m, m/s
// lanes as wide as the target's vector registers; by default one state a call without AVX
constexpr long native_width = long(kane::native_lanes<double>);
#if defined(__AVX__)
constexpr long default_width = native_width;
#else
constexpr long default_width = 1;
#endif
constexpr int bins = 12;

struct start {
  double lean, lean_rate, speed;
};

// Lane l of a number and of a status (W = 1: the number and the status themselves).
double lane(double x, std::size_t) { return x; }
kane::solve_status lane(kane::solve_status s, std::size_t) { return s; }
template <class T>
auto lane(const T& x, std::size_t l) {
  return x[l];
}

// The discs from s[0..count) for 3 s, W at once: upright[i] true if disc i stays upright and every
// step's status is ok. Lanes past count repeat s[0].
template <class S>
void stay_upright(rhs<S>& f, const start* s, std::size_t count, char* upright) {
  constexpr std::size_t W = kane::lane_traits<S>::width;
  const auto of = [&](auto g) {
    if constexpr (W == 1)
      return S(g(0));
    else
      return S::generate([&](std::size_t l) { return g(l < count ? l : 0); });
  };
  std::array<S, rhs<S>::size> x = {S(0.0),
                                   of([&](std::size_t l) { return s[l].lean; }),
                                   S(0.0),
                                   S(0.0),
                                   S(0.0),
                                   of([&](std::size_t l) { return s[l].lean_rate; }),
                                   of([&](std::size_t l) { return -s[l].speed / radius; }),
                                   S(0.0)};
  std::array<bool, W> up;
  up.fill(true);
  const double dt = 2e-3;
  for (int step = 0; step < 1500; ++step) {
    rk4_step(f, x, step * dt, dt);
    bool any = false;
    for (std::size_t l = 0; l < W; ++l) {
      up[l] = up[l] && lane(f.status(), l) == kane::solve_status::ok && std::abs(lane(x[1], l)) < 1.0;
      any = any || (up[l] && l < count);
    }
    if (!any) break;  // every disc of the batch has fallen
  }
  for (std::size_t l = 0; l < count; ++l) upright[l] = up[l];
}

// Every start, W at a time, split across threads; the run time in seconds.
template <class S>
double run(const std::vector<start>& starts, std::vector<char>& upright) {
  constexpr std::size_t W = kane::lane_traits<S>::width;
  const long n = long(starts.size()), batches = (n + long(W) - 1) / long(W);
  kane::state_of<d::system, d::speeds5, S> s;
  s.p = {S(radius), S(1.2), S(9.81)};  // r, m, g
  std::atomic<long> done{0};
  const auto t0 = std::chrono::steady_clock::now();
#if defined(_OPENMP)
#pragma omp parallel
#endif
  {
    rhs<S> f(s);  // one right-hand side per thread
#if defined(_OPENMP)
#pragma omp for schedule(dynamic, 4)
#endif
    for (long b = 0; b < batches; ++b) {
      const std::size_t first = std::size_t(b) * W, count = std::min(W, starts.size() - first);
      stay_upright(f, &starts[first], count, &upright[first]);
      const long k = ++done;
      if (k % (batches / 20 > 0 ? batches / 20 : 1) == 0)
        std::fprintf(stderr, "\r%3ld%% of %ld starts", 100 * k / batches, n);
    }
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void plot(const char* path, const std::array<int, bins>& up, const std::array<int, bins>& all) {
  FILE* svg = std::fopen(path, "w");
  if (!svg) return;
  const auto px = [](double v) { return 50 + 400 * v / top_speed; };
  const auto py = [](double fraction) { return 250 - 200 * fraction; };
  std::fprintf(svg,
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"480\" height=\"300\" font-size=\"12\">\n"
               "<rect width=\"480\" height=\"300\" fill=\"white\"/>\n"
               "<path d=\"M50 50V250H450\" stroke=\"black\" fill=\"none\"/>\n"
               "<text x=\"250\" y=\"285\" text-anchor=\"middle\">rolling speed, m/s</text>\n"
               "<text x=\"15\" y=\"150\" transform=\"rotate(-90 15 150)\" text-anchor=\"middle\">"
               "fraction upright after 3 s</text>\n");
  for (int k = 0; k <= 4; ++k)
    std::fprintf(svg, "<text x=\"45\" y=\"%.0f\" text-anchor=\"end\">%.2f</text>\n", py(k / 4.0) + 4,
                 k / 4.0);
  for (int k = 0; k <= 6; ++k)
    std::fprintf(svg, "<text x=\"%.0f\" y=\"265\" text-anchor=\"middle\">%.1f</text>\n",
                 px(k * top_speed / 6), k * top_speed / 6);
  std::fprintf(svg, "<polyline fill=\"none\" stroke=\"steelblue\" stroke-width=\"2\" points=\"");
  for (int b = 0; b < bins; ++b)
    if (all[std::size_t(b)] > 0)
      std::fprintf(svg, "%.1f,%.1f ", px((b + 0.5) * top_speed / bins),
                   py(double(up[std::size_t(b)]) / all[std::size_t(b)]));
  std::fprintf(svg, "\"/>\n</svg>\n");
  std::fclose(svg);
}

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000;
  const long width = (argc > 3 ? std::atol(argv[3]) : default_width) > 1 ? native_width : 1;
  std::vector<start> starts(std::size_t(n > 0 ? n : 0));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> lean(-0.2, 0.2), rate(-0.5, 0.5), speed(0.0, top_speed);
  for (auto& s : starts) s = {lean(rng), rate(rng), speed(rng)};
  std::vector<char> upright(starts.size());
  const double seconds = width == 1 ? run<double>(starts, upright)
                                    : run<kane::lanes<double, kane::native_lanes<double>>>(starts, upright);
  std::fprintf(stderr, "\n%ld starts in %.2f s, %ld a call\n", n, seconds, width);
  std::array<int, bins> up{}, all{};
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const int b = std::min(bins - 1, int(starts[i].speed / top_speed * bins));
    ++all[std::size_t(b)], up[std::size_t(b)] += upright[i];
  }
  std::printf("speed m/s  starts  upright\n");
  for (int b = 0; b < bins; ++b)
    std::printf("%4.1f-%3.1f  %6d  %6.3f\n", b * top_speed / bins, (b + 1) * top_speed / bins,
                all[std::size_t(b)],
                all[std::size_t(b)] ? double(up[std::size_t(b)]) / all[std::size_t(b)] : 0.0);
  if (argc > 2 && std::string_view(argv[2]) != "-") plot(argv[2], up, all);
  // slow discs fall and fast ones roll on: the fraction rises from the first bin to the last
  const bool pass =
      n < bins * 10 || (double(up[0]) / all[0] < 0.5 && double(up[bins - 1]) / all[bins - 1] > 0.9);
  std::printf(pass ? "slow discs fall, fast discs roll on\n" : "FAILED\n");
  return pass ? 0 : 1;
}
