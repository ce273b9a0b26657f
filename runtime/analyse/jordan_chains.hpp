/// @file Jordan chains (Hiller §6.3): for a matrix that is not diagonalizable, the
/// generalized eigenvectors v, (A − λI) v, …, (A − λI)^(k−1) v of each block, so that
/// x = V η turns x' = A x into η' = J η with J in Jordan form (λ on the diagonal, 1 above).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analyse/linear_system.hpp"

namespace eomgen::runtime {

struct JordanBasis {
  std::string refusal;  // why no basis was found, or empty
  Eigen::MatrixXcd V;   // the chains as columns, each chain's eigenvector first
  struct Block {
    std::complex<double> eigenvalue;
    int size = 1;
    Eigen::Index first = 0;  // its first column in V
  };
  std::vector<Block> blocks;
  /// the largest |B v_k − V_B J_k| / (|B| |v_k| + |v_(k−1)| within a chain) over V_B's columns v_k, on the
  /// balanced B = D⁻¹ A D (V = D V_B), J the Jordan form of `blocks`
  double residual = 0;
};

/// The chains of the blocks in `structure`: the dimensions of ker (A − λI)^j follow from
/// the block sizes, and the top of each chain is taken in ker (A − λI)^k outside
/// ker (A − λI)^(k−1) and the chains already chosen.
JordanBasis jordan_basis(const Eigen::MatrixXd& A, const JordanStructure& structure);

}  // namespace eomgen::runtime
