// Generalized speeds and constraints: speed sets and their
// kinematic differential equations, partial velocities, holonomic and
// nonholonomic constraints, all as types.
#pragma once

#include "kane/speeds/constraints.hpp"
#include "kane/speeds/generalized_speeds.hpp"
#include "kane/speeds/holonomic.hpp"
#include "kane/speeds/kinematic_weights.hpp"
#include "kane/speeds/partial_velocity.hpp"
