#include "analyse/principal_coordinates.hpp"

namespace eomgen::runtime {

PrincipalCoordinates principal_coordinates(const ModalAnalysis& modes, const Eigen::MatrixXd& second_order_inputs,
                                           const Eigen::MatrixXd& A, const Eigen::MatrixXd& state_inputs,
                                           const JordanStructure& structure) {
  PrincipalCoordinates p;
  bool decoupled = modes.refusal.empty() && !modes.modes.empty() && modes.damping != "nonproportional";
  if (decoupled) {
    p.kind = "modal";
    Eigen::Index n = static_cast<Eigen::Index>(modes.modes.size());
    p.modal_matrix.resize(n, n);
    for (Eigen::Index i = 0; i < n; ++i) p.modal_matrix.col(i) = modes.modes[static_cast<std::size_t>(i)].shape;
    p.modal_inputs = p.modal_matrix.transpose() * second_order_inputs;
    return p;
  }
  for (const EigenvalueStructure& e : structure.eigenvalues)
    if (e.geometric_multiplicity < e.algebraic_multiplicity) {
      p.kind = "none";
      p.reason = "A is not diagonalizable (a Jordan block of size > 1): the coordinates of a block stay coupled";
      return p;
    }
  Eigen::EigenSolver<Eigen::MatrixXd> solver(A, true);
  p.kind = "eigenvectors";
  p.eigenvectors = solver.eigenvectors();
  p.eigen_inputs = p.eigenvectors.partialPivLu().solve(state_inputs.cast<std::complex<double>>());
  for (Eigen::Index i = 0; i < A.rows(); ++i) p.eigenvalues.push_back(solver.eigenvalues()(i));
  return p;
}

}  // namespace eomgen::runtime
