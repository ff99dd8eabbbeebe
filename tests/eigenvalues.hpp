// The eigenvalues of a real square matrix by Eigen's EigenSolver, the reference of the tests,
// compiled once (eigenvalues.cpp): the solver is heavy to compile.
#pragma once

#include <Eigen/Core>

Eigen::VectorXcd eigenvalues_of(const Eigen::MatrixXd& a);
