// kane: kinematics of Kane's method with reference frames as types.
#pragma once

#include "kane/axis.hpp"
#include "kane/coordinate.hpp"
#include "kane/dcm.hpp"
#include "kane/express.hpp"
#include "kane/frame.hpp"
#include "kane/orientation.hpp"
#include "kane/scalar.hpp"
#include "kane/state.hpp"
#include "kane/vec.hpp"

// Printing: #include <kane/io.hpp> (kept out of the core).
