// Frames, coordinates and components: frame trees as types,
// states, components of vectors in a frame and direction cosines between frames.
#pragma once

#include "kane/frames/axis.hpp"
#include "kane/frames/dcm.hpp"
#include "kane/frames/express.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/orientation.hpp"
#include "kane/frames/state.hpp"
#include "kane/frames/vec.hpp"
#include "kane/scalars.hpp"  // q_i, parameters: a frame turns by them
