// Scalars: coordinates q_i, speeds u_r, parameters p_i, inputs r_i, time, and the scalar
// expressions of them (the leaves and nodes every later chapter builds on).
#pragma once

#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"
#include "kane/scalars/scalar.hpp"
