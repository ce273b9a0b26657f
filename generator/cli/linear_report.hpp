/// @file The report of `eomgen linear`: the linearized system about an equilibrium,
/// its eigenvalues with their multiplicities and Jordan blocks, the natural
/// frequencies and mass-normalized modes, and the fundamental matrix at given times.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/linear_system.hpp"
#include "analyse/modal_analysis.hpp"

namespace eomgen::cli {

struct LinearReport {
  std::vector<std::string> state_names;  // the whole state: cyclic coordinates are kept
  Eigen::MatrixXd A, B;                  // x' = A x + B u, from the generated Jacobians
  std::vector<double> characteristic_polynomial;  // det(λI − A), highest power first
  runtime::StabilityReport system;  // M, D, G, K, N of the second-order form
  runtime::JordanStructure structure;
  runtime::ModalAnalysis modes;
  std::vector<std::pair<double, Eigen::MatrixXd>> fundamental;  // (t, Φ(t))
};

/// Everything `linear` prints, at the equilibrium x.
LinearReport linear_report(const runtime::Problem& problem, const std::vector<double>& x, const std::vector<double>& times);

void print_linear_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r);
void print_linear_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r);

}  // namespace eomgen::cli
