// Expressions: scalars in q, q', u, t and parameters; vectors as sums of
// scalars times unit vectors of frames, with cross and dot products.
#pragma once

#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/direction_cosines.hpp"
#include "kane/expressions/known_values.hpp"
#include "kane/expressions/nodes.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/scalars.hpp"  // scalar expressions
