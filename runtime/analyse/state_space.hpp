/// @file The linear system x' = A x + B u, y = C x + D u of a compiled model about an
/// equilibrium or steady motion, on the whole state.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

struct StateSpace {
  Eigen::MatrixXd A, B;  // from the generated Jacobians: exact where q'' = 0
};

StateSpace state_space_at(const Problem& problem, const std::vector<double>& x);

/// C and D of the named outputs: a state is read exactly; an [outputs] entry is differentiated
/// centrally (h = 1e-6 times the size of the variable, error about 1e-10 relative).
void output_matrices(const Problem& problem, const std::vector<double>& x, const std::vector<std::string>& names,
                     Eigen::MatrixXd& C, Eigen::MatrixXd& D);

}  // namespace eomgen::runtime
