#include "analyse/principal_coordinates.hpp"

#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

// V⁻¹ B; Eigen's triangular solve reads the first entry of an empty right-hand side, so a
// model without inputs gets its empty matrix directly
Eigen::MatrixXcd solve_inputs(const Eigen::MatrixXcd& V, const Eigen::MatrixXd& B) {
  if (B.cols() == 0) return Eigen::MatrixXcd(V.rows(), 0);
  return V.partialPivLu().solve(B.cast<std::complex<double>>());
}

// x = V η with the Jordan chains (Hiller §6.3): the blocks stay coupled only along their chains
PrincipalCoordinates jordan_coordinates(const Eigen::MatrixXd& A, const Eigen::MatrixXd& state_inputs,
                                        const JordanStructure& structure) {
  PrincipalCoordinates p;
  p.kind = "none";
  if (structure.uncertain) {
    p.reason = "A is not diagonalizable, and its Jordan structure is uncertain numerically, so no chains are formed";
    return p;
  }
  JordanBasis basis = jordan_basis(A, structure);
  if (!basis.refusal.empty()) {
    p.reason = "A is not diagonalizable: " + basis.refusal;
    return p;
  }
  p.kind = "jordan";
  p.eigenvectors = basis.V;
  p.eigen_inputs = solve_inputs(basis.V, state_inputs);
  p.jordan_residual = basis.residual;
  for (const JordanBasis::Block& b : basis.blocks)
    for (int i = 0; i < b.size; ++i) p.eigenvalues.push_back(b.eigenvalue), p.chained.push_back(i + 1 < b.size);
  return p;
}

}  // namespace

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
    if (e.geometric_multiplicity < e.algebraic_multiplicity) return jordan_coordinates(A, state_inputs, structure);
  // on the balanced D⁻¹ A D = W Λ W⁻¹ (Eigen's solver does not balance: the eigenvalues of a
  // two-mass oscillator at 1e7 rad/s came out 1 % off), then V = D W N⁻¹ with N scaling V's
  // columns to length one, and V⁻¹ B = N W⁻¹ D⁻¹ B
  Eigen::VectorXd d = balancing_scales(A);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(d.cwiseInverse().asDiagonal() * A * d.asDiagonal(), true);
  const Eigen::MatrixXcd& W = solver.eigenvectors();
  Eigen::MatrixXcd V = d.cast<std::complex<double>>().asDiagonal() * W;
  Eigen::VectorXd lengths = V.colwise().norm().transpose();
  p.kind = "eigenvectors";
  p.eigenvectors = V * lengths.cwiseInverse().cast<std::complex<double>>().asDiagonal();
  p.eigen_inputs = lengths.cast<std::complex<double>>().asDiagonal() *
                   solve_inputs(W, d.cwiseInverse().asDiagonal() * state_inputs);
  for (Eigen::Index i = 0; i < A.rows(); ++i) p.eigenvalues.push_back(solver.eigenvalues()(i));
  return p;
}

}  // namespace eomgen::runtime
