// Frames, coordinates and components: frame trees as types,
// states, components of vectors in a frame and direction cosines between frames.
#pragma once

#include "kane/frames/axis.hpp"
#include "kane/frames/coordinate.hpp"
#include "kane/frames/dcm.hpp"
#include "kane/frames/express.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/orientation.hpp"
#include "kane/frames/scalar.hpp"
#include "kane/frames/state.hpp"
#include "kane/frames/vec.hpp"
