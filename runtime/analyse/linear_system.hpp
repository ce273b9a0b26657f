/// @file The solution of the linearized system x' = A x + B u (Hiller §6): the
/// eigenvalues with their algebraic and geometric multiplicities and Jordan block
/// sizes, and the fundamental matrix Φ(t) = e^{At}.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace eomgen::runtime {

struct EigenvalueStructure {
  std::complex<double> value;   // the mean of a cluster of computed eigenvalues
  int algebraic_multiplicity = 1;
  int geometric_multiplicity = 1;
  std::vector<int> jordan_blocks;  // sizes, largest first
};

struct JordanStructure {
  std::vector<EigenvalueStructure> eigenvalues;  // by decreasing real part, then imaginary part
  /// Ranks are decided numerically: singular values below rank_tolerance count as zero.
  double rank_tolerance = 0;
  /// Some singular value lies within a factor 100 of the tolerance: the multiplicities could
  /// be different for a nearby matrix, and the report says so instead of guessing.
  bool uncertain = false;
};

/// Eigenvalues clustered within 1e-4·max(1, |A|) and the ranks of (A − λI)^k, k = 1 … m:
/// the number of Jordan blocks of size ≥ k is rank_{k−1} − rank_k.
JordanStructure jordan_structure(const Eigen::MatrixXd& A);

/// Φ(t) = e^{At}, by scaling and squaring with a Padé approximant.
Eigen::MatrixXd fundamental_matrix(const Eigen::MatrixXd& A, double t);

}  // namespace eomgen::runtime
