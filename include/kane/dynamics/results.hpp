// The results of the dynamics' entry points: each a struct of named fields and a status. When the
// status is not ok, the numbers are NaN.
//
//   const auto [M, f, status] = kane::mass_matrix_and_forcing<System>(ev);   // equations_of_motion
//   const auto [ud, status] = kane::forward_dynamics<System>(ev);            // forward_result
//   const auto [tau, status] = kane::inverse_dynamics<System>(ev);           // inverse_result
//   const auto [f, status] = kane::forcing<System>(ev);                      // forcing_result
//   const auto [tau, dq, du, M, status] = kane::inverse_dynamics_derivatives<System>(ev);
//   const auto [ud, dq, du, status] = kane::forward_dynamics_derivatives<System>(ev);
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "kane/evaluation/status.hpp"

namespace kane {

// M u' = f of N speeds at a state: mass_matrix_and_forcing.
template <class S, std::size_t N>
struct equations_of_motion {
  // the mass matrix, N x N
  Eigen::Matrix<S, int(N), int(N)> M;  // symmetric, positive definite for a system with mass in every speed
  // the forcing, N x 1
  Eigen::Matrix<S, int(N), 1> f;
  // ok, or why M and f are NaN
  status_of<S> status;  // the evaluator's, or not_finite
};

// M alone: mass_matrix.
template <class S, std::size_t N>
struct mass_matrix_only {
  // the mass matrix, N x N
  Eigen::Matrix<S, int(N), int(N)> M;
  // the evaluator's, or not_finite
  status_of<S> status;
};

// u' = M^-1 f: forward_dynamics, speed_derivatives.
template <class S, std::size_t N>
struct forward_result {
  // u'_1 .. u'_N
  Eigen::Matrix<S, int(N), 1> ud;
  // the evaluator's, singular (M not positive definite) or not_finite
  status_of<S> status;
};

// tau = M u' - f: inverse_dynamics.
template <class S, std::size_t N>
struct inverse_result {
  // the generalized forces that, added to the system's loads, give the state's u'
  Eigen::Matrix<S, int(N), 1> tau;
  // the evaluator's, or not_finite
  status_of<S> status;
};

// f alone (the bias -f is tau at u' = 0): forcing.
template <class S, std::size_t N>
struct forcing_result {
  // the forcing, N x 1
  Eigen::Matrix<S, int(N), 1> f;
  // the evaluator's, or not_finite
  status_of<S> status;
};

// tau and its derivatives: inverse_dynamics_derivatives.
template <class S, std::size_t N>
struct inverse_derivatives {
  // tau = M u' - f at the state
  Eigen::Matrix<S, int(N), 1> tau;
  // d tau / dq: column i by q_i
  Eigen::Matrix<S, int(N), int(N)> dtau_dq;
  // d tau / du: column r by u_r
  Eigen::Matrix<S, int(N), int(N)> dtau_du;
  // d tau / du', the mass matrix
  Eigen::Matrix<S, int(N), int(N)> M;
  // the evaluator's, or not_finite
  status_of<S> status;
};

// u' and its derivatives: forward_dynamics_derivatives.
template <class S, std::size_t N>
struct forward_derivatives {
  // u' = M^-1 f at the state
  Eigen::Matrix<S, int(N), 1> ud;
  // d u' / dq = -M^-1 d tau / dq
  Eigen::Matrix<S, int(N), int(N)> dud_dq;
  // d u' / du = -M^-1 d tau / du
  Eigen::Matrix<S, int(N), int(N)> dud_du;
  // the evaluator's, singular (M not positive definite) or not_finite
  status_of<S> status;
};

}  // namespace kane
