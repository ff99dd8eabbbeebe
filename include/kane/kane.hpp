// kane: Kane's method with reference frames as types. The chapters, each
// including only the ones above it:
#pragma once

#include "kane/evaluation.hpp"   // the evaluator and the numbers of all of the above
#include "kane/expressions.hpp"  // scalar and vector expressions
#include "kane/frames.hpp"       // frames, coordinates, components, direction cosines
#include "kane/kinematics.hpp"   // derivatives, angular velocities, points
#include "kane/speeds.hpp"       // generalized speeds, partial velocities, constraints

// Printing: #include <kane/print.hpp> (kept out of the core).
