// The benchmark bicycle's linearization, compiled once (the declarations: bicycle_linear.hpp).
#include "bicycle_linear.hpp"

#include <type_traits>

#include "bicycle.hpp"

namespace models::bicycle {
lean_steer linearize_upright(double v) {
  dynamics_state s = benchmark_parameters();
  s.u[6] = v / s.p[1];
  const auto eq = kane::linearize_equations<system, rolling, dynamics_evaluator, pitch>(s);
  using E = std::remove_cvref_t<decltype(eq)>;  // rows by speed, K's columns by coordinate
  constexpr Eigen::Index roll = E::row(kane::u<4>), steer = E::row(kane::u<6>);
  const auto block = [&](const auto& m, Eigen::Index c0, Eigen::Index c1) {
    return (Eigen::Matrix2d() << m(roll, c0), m(roll, c1), m(steer, c0), m(steer, c1)).finished();
  };
  return {block(eq.M, roll, steer), block(eq.C, roll, steer),
          block(eq.K, E::index(kane::q<4>), E::index(kane::q<6>)), eq.status};
}

}  // namespace models::bicycle
