// The free body's motion (models/free_body.hpp with no load), compiled once in
// free_body_motion.cpp behind plain functions: x = (q1..q7, u1..u6), a body of mass m and
// principal moments I1, I2, I3 about its mass centre.
#pragma once

#include <array>

#include <kane/evaluation/status.hpp>

namespace models::free_body {
struct mass_properties {
  double m, I1, I2, I3;
};
using motion_vector = std::array<double, 13>;

// x' at x by Kane's equations (kane::motion); its status.
kane::solve_status motion_rates(const mass_properties& b, const motion_vector& x, motion_vector& dxdt);
// T at x.
double kinetic_energy(const mass_properties& b, const motion_vector& x);
}  // namespace models::free_body
