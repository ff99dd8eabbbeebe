// A user's unit that holds the whole Whipple bicycle: u' by kane::constrained_motion, Kane's reduced
// equations, F_r and F*_r of every speed as expressions, the linearization about upright running
// and its eigenvalues. Compiled by benchmarks/compile_cost.sh for the compile table; it prints
// F_r + F*_r against f - M u' and the eigenvalues at 5 m/s.
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstdio>
#include <kane/kane.hpp>
#include <type_traits>
#include <utility>

#include "models/bicycle.hpp"

namespace b = models::bicycle;

int main() {
  b::dynamics_state s = b::benchmark_parameters();
  s.q = {0, 0, 0.1, 0.05, 0, 0.2};
  kane::constrained_motion<b::system, b::rolling, b::dynamics_evaluator> rhs(s);
  std::array<double, 9> x{0, 0, 0.1, 0.05, 0, 0.2, 0.3, -0.2, 12}, dx{};
  rhs(x, dx, 0.0);
  const auto red = kane::reduced_mass_matrix_and_forcing<b::system, b::rolling>(
      rhs.evaluator(), kane::solve_constraints<b::rolling>(rhs.evaluator()));
  // F_r + F*_r = f_r - (M u')_r for every speed, at the u' of the constrained motion
  b::dynamics_state at = rhs.state();
  const Eigen::Matrix<double, 8, 1> ud = red.T * Eigen::Vector3d(dx[6], dx[7], dx[8]) + red.b;
  for (int i = 0; i < 8; ++i) at.ud[std::size_t(i)] = ud(i);
  b::dynamics_evaluator ev;
  ev.update(at);
  const auto eom = kane::mass_matrix_and_forcing<b::system>(ev);
  const Eigen::Matrix<double, 8, 1> expected = eom.f - eom.M * ud;
  double worst = 0;
  [&]<std::size_t... R>(std::index_sequence<R...>) {
    ((worst = std::fmax(
          worst,
          std::fabs(kane::evaluate(kane::generalized_active_force<b::N, b::system, b::speeds, R + 1>(), ev) +
                    kane::evaluate(kane::generalized_inertia_force<b::N, b::system, b::speeds, R + 1>(), ev) -
                    expected(R)))),
     ...);
  }
  (std::make_index_sequence<8>{});
  std::printf("reduced f: %.6f %.6f %.6f; largest |F_r + F*_r - (f - M u')_r|: %.1e\n", red.reduced.f(0),
              red.reduced.f(1), red.reduced.f(2), worst);
  // upright, 5 m/s: M u' + C u + K q = 0 in roll and steer, its eigenvalues
  b::dynamics_state up = b::benchmark_parameters();
  up.u[6] = 5.0 / up.p[1];
  const auto eq = kane::linearize_equations<b::system, b::rolling, b::dynamics_evaluator, b::pitch>(up);
  using E = std::remove_cvref_t<decltype(eq)>;
  constexpr Eigen::Index roll = E::row(kane::u<4>), steer = E::row(kane::u<6>);
  const Eigen::Index qr = E::index(kane::q<4>), qs = E::index(kane::q<6>);
  Eigen::Matrix2d m, c, k;
  m << eq.M(roll, roll), eq.M(roll, steer), eq.M(steer, roll), eq.M(steer, steer);
  c << eq.C(roll, roll), eq.C(roll, steer), eq.C(steer, roll), eq.C(steer, steer);
  k << eq.K(roll, qr), eq.K(roll, qs), eq.K(steer, qr), eq.K(steer, qs);
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a.topRightCorner<2, 2>().setIdentity();
  a.bottomLeftCorner<2, 2>() = -m.inverse() * k;
  a.bottomRightCorner<2, 2>() = -m.inverse() * c;
  const auto eig = kane::eigenvalues(a);
  std::printf("eigenvalues at 5 m/s:");
  for (int i = 0; i < 4; ++i) std::printf(" %.4f%+.4fi", eig.values(i).real(), eig.values(i).imag());
  std::printf("\n");
  return rhs.status() == kane::solve_status::ok && eq.status == kane::solve_status::ok &&
                 eig.status == kane::solve_status::ok && worst < 1e-9
             ? 0
             : 1;
}
