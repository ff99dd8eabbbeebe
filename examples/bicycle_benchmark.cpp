// The Whipple bicycle benchmark (Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463,
// 2007) from kane's typed model (models/bicycle.hpp): Kane's reduced equations for roll u4,
// steer u6 and rear wheel u7, linearized exactly (jets) about upright straight running at
// speed v, give M u' + C u + K q = 0. Their roll/steer block is the paper's
// M phi'' + v C1 phi' + (g K0 + v^2 K2) phi = 0 with phi = (roll q4, steer q6).
// Printed and checked: M, C1, K0, K2 against the paper's values; the eigenvalues over
// 0 <= v <= 10; the weave and capsize speeds by bisection on the real parts.
// Arguments (optional): a CSV file of v and the eigenvalues, an SVG picture of them.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "models/bicycle_linear.hpp"

namespace {
namespace b = models::bicycle;
using matrix = Eigen::Matrix2d;
using b::linearize_upright;
const auto eigenvalues = b::upright_eigenvalues;

using b::bisect;
const auto weave = b::weave_real_part;
const auto capsize = b::capsize_eigenvalue;

int check(const char* what, const matrix& kane, const matrix& paper) {
  const double err = (kane - paper).cwiseAbs().maxCoeff() / paper.cwiseAbs().maxCoeff();
  std::printf("%-3s [% .14f % .14f; % .14f % .14f]  relative error %.1e\n", what, kane(0, 0), kane(0, 1),
              kane(1, 0), kane(1, 1), err);
  return err < 1e-12 ? 0 : 1;
}

void svg(const char* path) {
  FILE* f = std::fopen(path, "w");
  if (!f) return;
  const auto x = [](double v) { return 60 + 52 * v; };
  const auto y = [](double l) { return 220 - 20 * l; };
  std::fprintf(f,
               "<svg xmlns='http://www.w3.org/2000/svg' width='620' height='460' font-family='sans-serif' "
               "font-size='13'>\n<rect width='620' height='460' fill='white'/>\n");
  for (int t = -10; t <= 10; t += 5)
    std::fprintf(f, "<line x1='60' x2='580' y1='%g' y2='%g' stroke='#ddd'/><text x='30' y='%g'>%d</text>\n",
                 y(t), y(t), y(t) + 4, t);
  for (int v = 0; v <= 10; v += 2) std::fprintf(f, "<text x='%g' y='440'>%d</text>\n", x(v) - 4, v);
  std::fprintf(f,
               "<line x1='60' x2='580' y1='%g' y2='%g' stroke='black'/><text x='250' y='456'>speed v "
               "(m/s)</text>\n<text x='70' y='30'>eigenvalues: real parts (blue), imaginary parts (orange), "
               "Meijaard et al. 2007</text>\n",
               y(0), y(0));
  for (const bool imaginary : {false, true}) {  // one path of small squares per colour
    std::fprintf(f, "<path fill='%s' d='", imaginary ? "#e07b00" : "#1f5fbf");
    for (int i = 0; i <= 500; ++i)
      for (auto e : eigenvalues(i / 50.0))
        if (const double l = imaginary ? e.imag() : e.real(); std::abs(l) <= 10 && (!imaginary || l > 0))
          std::fprintf(f, "M%.1f %.1fh2v2h-2z", x(i / 50.0) - 1, y(l) - 1);
    std::fprintf(f, "'/>\n");
  }
  for (const double v : {4.29238253634111, 6.02426201538837})
    std::fprintf(f, "<line x1='%.1f' x2='%.1f' y1='20' y2='420' stroke='gray' stroke-dasharray='4'/>\n", x(v),
                 x(v));
  std::fprintf(f, "</svg>\n");
  std::fclose(f);
}
}  // namespace

int main(int argc, char** argv) {
  const b::lean_steer at0 = linearize_upright(0), at5 = linearize_upright(5);
  int failures = (at0.status != kane::solve_status::ok) + (at5.status != kane::solve_status::ok);
  // Meijaard et al. (2007), section 5 (the benchmark's coefficient matrices)
  const matrix M{{80.81722, 2.31941332208709}, {2.31941332208709, 0.29784188199686}};
  const matrix C1{{0, 33.86641391492494}, {-0.85035641456978, 1.68540397397560}};
  const matrix K0{{-80.95, -2.59951685249872}, {-2.59951685249872, -0.80329488458618}};
  const matrix K2{{0, 76.59734589573222}, {0, 2.65431523794604}};
  const double g = 9.81;
  failures += check("M", at0.M, M);
  failures += check("C1", at5.C / 5, C1);
  failures += check("K0", at0.K / g, K0);
  failures += check("K2", (at5.K - at0.K) / 25, K2);

  const double vw = bisect(weave, 4, 5), vc = bisect(capsize, 5.5, 6.5);
  std::printf("weave speed   %.14f (paper 4.29238253634111)\ncapsize speed %.14f (paper 6.02426201538837)\n",
              vw, vc);
  failures += !(std::abs(vw - 4.29238253634111) < 1e-10) + !(std::abs(vc - 6.02426201538837) < 1e-10);

  std::printf("\n   v    eigenvalues (real, imaginary)\n");
  for (int v = 0; v <= 10; ++v) {
    std::printf("%4d ", v);
    for (auto e : eigenvalues(v)) std::printf("  % 9.5f%+9.5fi", e.real(), e.imag());
    std::printf("\n");
  }
  if (argc > 1)
    if (FILE* csv = std::fopen(argv[1], "w")) {
      std::fprintf(csv, "v,re1,im1,re2,im2,re3,im3,re4,im4\n");
      for (int i = 0; i <= 1000; ++i) {
        std::fprintf(csv, "%.2f", i / 100.0);
        for (auto e : eigenvalues(i / 100.0)) std::fprintf(csv, ",%.15g,%.15g", e.real(), e.imag());
        std::fprintf(csv, "\n");
      }
      std::fclose(csv);
    }
  if (argc > 2) svg(argv[2]);
  std::printf("%s\n", failures ? "FAILED" : "all checks passed");
  return failures ? 1 : 0;
}
