// kane: kinematics of Kane's method with reference frames as types.
#pragma once

#include "kane/angular_velocity.hpp"
#include "kane/axis.hpp"
#include "kane/constraints.hpp"
#include "kane/coordinate.hpp"
#include "kane/dcm.hpp"
#include "kane/derivative.hpp"
#include "kane/evaluator.hpp"
#include "kane/expr.hpp"
#include "kane/express.hpp"
#include "kane/frame.hpp"
#include "kane/orientation.hpp"
#include "kane/partial_velocity.hpp"
#include "kane/point.hpp"
#include "kane/scalar.hpp"
#include "kane/speeds.hpp"
#include "kane/state.hpp"
#include "kane/vec.hpp"
#include "kane/vector.hpp"

// Printing: #include <kane/print.hpp> (kept out of the core).
