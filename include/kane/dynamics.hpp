// Dynamics (Kane's dynamical equations): particles, rigid bodies and loads;
// M(q, t) u' = f(q, u, t) from the partial velocities.
#pragma once

#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/constrained_motion.hpp"
#include "kane/dynamics/dynamics_derivatives.hpp"
#include "kane/dynamics/forward_dynamics.hpp"
#include "kane/dynamics/generalized_forces.hpp"
#include "kane/dynamics/inverse_dynamics.hpp"
#include "kane/dynamics/loads.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/dynamics/momenta.hpp"
#include "kane/dynamics/motion.hpp"
#include "kane/dynamics/reaction.hpp"
#include "kane/dynamics/reduced_equations.hpp"
#include "kane/dynamics/results.hpp"
#include "kane/dynamics/springs.hpp"
#include "kane/dynamics/system_evaluator.hpp"
