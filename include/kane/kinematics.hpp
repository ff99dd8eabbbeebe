// Kinematics: derivatives in a frame, angular velocities and
// accelerations with the addition theorem, points, velocities and accelerations.
#pragma once

#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/derivative_traits.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/kinematics/point.hpp"
