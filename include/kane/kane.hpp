// kane: Kane's method with reference frames as types. The chapters, in order,
// each including only the ones above it:
#pragma once

#include "kane/detail/frame_check.hpp"  // first: a broken rule's error names it in its first lines

// coordinates, speeds, parameters, inputs and their scalar expressions
#include "kane/scalars.hpp"

// frames, components, direction cosines
#include "kane/frames.hpp"

// vector expressions
#include "kane/expressions.hpp"

// derivatives, angular velocities, points
#include "kane/kinematics.hpp"

// generalized speeds, partial velocities, constraints
#include "kane/speeds.hpp"

// the evaluator and the numbers of all of the above
#include "kane/evaluation.hpp"

// particles, rigid bodies, loads and Kane's dynamical equations
#include "kane/dynamics.hpp"

// linearization about a state by exact (forward-mode) derivatives
#include "kane/linearization.hpp"

// Printing: #include <kane/print.hpp> (kept out of the core).
