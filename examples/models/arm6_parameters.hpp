// The 6-revolute arm's links as numbers (no kane): lengths, masses, inertias about the
// mass centres in the links' frames, gravity. Shared by arm6_dynamics.hpp and the
// hand-written and KDL baselines of benchmarks/dynamics6.
#pragma once

namespace models::arm6 {
inline constexpr double length[6] = {0.3, 0.25, 0.2, 0.15, 0.1, 0.05};
inline constexpr double mass[6] = {2.0, 1.6, 1.2, 0.8, 0.5, 0.3};
// I11, I22, I33, I12, I23, I31 of link i about its mass centre, in B_i
inline constexpr double inertia[6][6] = {
    {0.020, 0.030, 0.025, 0.002, -0.001, 0.0015},     {0.015, 0.022, 0.018, -0.0012, 0.0008, 0.001},
    {0.010, 0.014, 0.012, 0.0009, -0.0006, -0.0007},  {0.006, 0.008, 0.007, -0.0005, 0.0004, 0.0003},
    {0.003, 0.004, 0.0035, 0.0002, -0.0002, 0.00025}, {0.0015, 0.002, 0.0018, -0.0001, 0.0001, 0.00012}};
inline constexpr double g = 9.81;
}  // namespace models::arm6
