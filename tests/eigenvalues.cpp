#include "eigenvalues.hpp"

#include <Eigen/Eigenvalues>

Eigen::VectorXcd eigenvalues_of(const Eigen::MatrixXd& a) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues();
}
