// Evaluation: the evaluator (outward pass over the frame tree, kinematic
// differential equations), node evaluation and the numeric tables of Kane's method.
#pragma once

#include "kane/evaluation/configuration.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/evaluation/evaluator_for.hpp"
#include "kane/evaluation/expression_reads.hpp"
#include "kane/evaluation/kinematic_equations.hpp"
#include "kane/evaluation/nonholonomic_tables.hpp"
#include "kane/evaluation/outward_pass.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/evaluation/tables.hpp"
