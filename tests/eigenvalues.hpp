// The eigenvalues of a real square matrix, compiled once (eigenvalues.cpp): Eigen's EigenSolver
// costs the unit that instantiates it about 14 s of g++ and 0.5 GB.
#pragma once

#include <Eigen/Core>

Eigen::VectorXcd eigenvalues_of(const Eigen::MatrixXd& a);
