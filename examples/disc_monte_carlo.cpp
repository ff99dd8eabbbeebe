// A Monte Carlo of the rolling disc (models/disc.hpp): random initial lean, lean rate and rolling
// speed, each start integrated 3 s by RK4 (dt = 2 ms) through kane::constrained_motion. A start stays
// upright if |lean| stays below 1 rad. The fraction that stays upright, by speed, is printed and, with a
// path, plotted as SVG. The starts are split across OpenMP threads (g++ -fopenmp), one right-hand side per
// thread; without OpenMP they run in one thread with the same results. A progress line goes to stderr.
//
//   example_disc_monte_carlo [starts] [plot.svg]
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "models/disc.hpp"
#include "rk4.hpp"

namespace d = models::disc;
using rhs = kane::constrained_motion<d::system, d::rolling>;
using vector = std::array<double, rhs::size>;  // yaw, lean, spin angle, x, y, u1, u2, u3

constexpr double radius = 0.3, top_speed = 3.6;  // m, m/s
constexpr int bins = 12;

struct start {
  double lean, lean_rate, speed;
};

// The disc from s for 3 s: true if it stays upright and every step's status is ok.
bool stays_upright(rhs& f, const start& s) {
  vector x = {0.0, s.lean, 0.0, 0.0, 0.0, s.lean_rate, -s.speed / radius, 0.0};
  const double dt = 2e-3;
  for (int step = 0; step < 1500; ++step) {
    rk4_step(f, x, step * dt, dt);
    if (f.status() != kane::solve_status::ok || !(std::abs(x[1]) < 1.0)) return false;
  }
  return true;
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
  std::vector<start> starts(std::size_t(n > 0 ? n : 0));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> lean(-0.2, 0.2), rate(-0.5, 0.5), speed(0.0, top_speed);
  for (auto& s : starts) s = {lean(rng), rate(rng), speed(rng)};
  std::vector<char> upright(starts.size());
  kane::state_of<d::system, d::speeds5> s;
  s.p = {radius, 1.2, 9.81};  // r, m, g
  std::atomic<long> done{0};
  const auto t0 = std::chrono::steady_clock::now();
#if defined(_OPENMP)
#pragma omp parallel
#endif
  {
    rhs f(s);  // one right-hand side per thread
#if defined(_OPENMP)
#pragma omp for schedule(dynamic, 16)
#endif
    for (long i = 0; i < n; ++i) {
      upright[std::size_t(i)] = stays_upright(f, starts[std::size_t(i)]);
      const long k = ++done;
      if (k % (n / 20 > 0 ? n / 20 : 1) == 0) std::fprintf(stderr, "\r%3ld%% of %ld starts", 100 * k / n, n);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr, "\n%ld starts in %.2f s\n", n, seconds);
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
  if (argc > 2) plot(argv[2], up, all);
  // slow discs fall and fast ones roll on: the fraction rises from the first bin to the last
  const bool pass =
      n < bins * 10 || (double(up[0]) / all[0] < 0.5 && double(up[bins - 1]) / all[bins - 1] > 0.9);
  std::printf(pass ? "slow discs fall, fast discs roll on\n" : "FAILED\n");
  return pass ? 0 : 1;
}
