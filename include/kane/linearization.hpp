// Linearization: exact first derivatives by jets through the evaluator; A, B of
// x' = f(x, r) and the second-order form M u' + C u + K q = B r.
#pragma once

#include "kane/linearization/eigenvalues.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/linear_model.hpp"
#include "kane/linearization/linearize.hpp"
#include "kane/linearization/tangent.hpp"
