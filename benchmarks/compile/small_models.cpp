// Six small models and two linearizations as a user's one unit: x' of the heavy top, the
// reaction-wheel spacecraft, the double pendulum on absolute angles, the 3D double pendulum, the
// cart with three links (kane::motion) and the rolling disc (kane::constrained_motion); A and B of
// the 3D double pendulum and of the cart (kane::linearize). The compile table gives its cost.
#include <array>
#include <cstdio>

#include "../../examples/models/cart_pendulum.hpp"
#include "../../examples/models/disc.hpp"
#include "../../examples/models/gyrostat.hpp"
#include "../../examples/models/heavy_top.hpp"
#include "../../examples/models/pendulum3d.hpp"
#include "../../examples/models/pendulum_absolute.hpp"

namespace {
// x' at x of the right-hand side f, the sum of its entries
template <class F, class X>
double rates(F& f, const X& x) {
  X dx{};
  f(x, dx, 0.0);
  double sum = 0;
  for (const double v : dx) sum += v;
  return sum;
}
}  // namespace

int main() {
  double sum = 0;
  {
    namespace m = models::heavy_top;
    kane::motion<m::system, m::speeds> f{m::state{}};
    sum += rates(f, std::array<double, 6>{0.1, 0.5, 0.2, 1, 2, 3});
  }
  {
    namespace m = models::gyrostat;
    kane::motion<m::system, m::speeds> f{m::state{}};
    sum += rates(f, std::array<double, 14>{1, 0, 0, 0, 0, 0, 0, 0.1, 0.2, 0.3, 1, 0, 0, 5});
  }
  {
    namespace m = models::pendulum_absolute;
    kane::motion<m::system> f{kane::state_of<m::system>{}};
    sum += rates(f, std::array<double, 4>{0.3, -0.2, 1, 0.5});
  }
  models::pendulum3d::state pd;
  pd.q = {0.3, -0.5};
  pd.u = {0.7, 0.2};
  pd.p = {1,    0.8,  2,    1.5,   0.5,    0.1,   0.12, 0.03, 0.01, 0.02, -0.01,
          0.09, 0.08, 0.02, 0.005, -0.004, 0.003, 9.81, 3,    0.4,  0.2};
  {
    namespace m = models::pendulum3d;
    kane::motion<m::system, m::evaluator> f(pd);
    sum += rates(f, std::array<double, 4>{0.3, -0.5, 0.7, 0.2});
  }
  models::cart_pendulum::state cp;
  cp.q = {0.1, 0.2, -0.3, 0.4};
  cp.u = {0.5, -0.1, 0.2, 0.3};
  cp.p = {0.5, 1, 2, 9.81};
  {
    namespace m = models::cart_pendulum;
    kane::motion<m::system, m::evaluator> f(cp);
    sum += rates(f, std::array<double, 8>{0.1, 0.2, -0.3, 0.4, 0.5, -0.1, 0.2, 0.3});
  }
  {
    namespace m = models::disc;
    using rhs = kane::constrained_motion<m::system, m::rolling>;
    rhs::state_type s{};
    s.p = {0.3, 2, 9.81};
    rhs f(s);
    sum += rates(f, std::array<double, 8>{0.1, 0.2, 0.3, 0, 0, 0.5, 4, -0.2});
  }
  {
    namespace m = models::pendulum3d;
    const auto lin = kane::linearize<m::system, m::evaluator, kane::inputs<m::p<19>>>(pd);
    sum += lin.A(2, 0) + lin.B(3, 0);
  }
  {
    namespace m = models::cart_pendulum;
    const auto lin = kane::linearize<m::system, m::evaluator>(cp);
    sum += lin.A(4, 1);
  }
  std::printf("%.6f\n", sum);
  return 0;
}
