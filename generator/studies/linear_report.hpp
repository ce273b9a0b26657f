/// @file The report of `eomgen linear`: the linearized system about an equilibrium,
/// its eigenvalues with their multiplicities and Jordan blocks, the natural
/// frequencies and mass-normalized modes, and the fundamental matrix at given times.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analyse/controllability.hpp"
#include "analyse/equilibrium.hpp"
#include "symbolic_analysis/exact_jordan.hpp"
#include "symbolic_analysis/deformed_shapes.hpp"
#include "symbolic_analysis/linear_closed_form.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/linear_system.hpp"
#include "analyse/principal_coordinates.hpp"
#include "analyse/modal_analysis.hpp"

namespace eomgen::studies {

struct LinearReport {
  std::vector<std::string> state_names;  // the whole state: cyclic coordinates are kept
  Eigen::MatrixXd A, B;                  // x' = A x + B u, from the generated Jacobians
  std::vector<double> characteristic_polynomial;  // det(λI − A), highest power first
  runtime::StabilityReport system;  // M, D, G, K, N of the second-order form
  runtime::JordanStructure structure;
  ExactJordan exact;    // the structure by exact arithmetic, when A is rational
  bool decided_exactly = false;  // `structure` then holds the exact multiplicities and blocks
  runtime::ModalAnalysis modes;
  DeformedShapes deformed;  // pictures of the modes, from the bodies' positions
  runtime::PrincipalCoordinates principal;
  std::vector<std::pair<double, Eigen::MatrixXd>> fundamental;  // (t, Φ(t))
  std::vector<std::string> input_names, output_names;
  Eigen::MatrixXd C, D;  // y = C x + D u; model outputs by central differences, states exactly
  runtime::Reach reach;  // controllability from all inputs, observability from all outputs
  struct Pair {
    std::string input, output;
    runtime::TransferFunction g;
  };
  std::vector<Pair> transfer;
  std::optional<LinearClosedForm> closed_form;  // with --symbolic
  std::vector<std::string> closed_form_outputs;  // the rows of its transfer functions
};

struct LinearRequest {
  std::vector<double> times;
  std::vector<std::string> outputs;                              // state or output names; empty: the model's outputs
  std::vector<std::pair<std::string, std::string>> transfer;     // (input, output)
  bool symbolic = false;                                         // Φ(t) and G(s) in closed form
};

/// The names in `request` that are not inputs, states or outputs, or empty.
std::string unknown_names(const eomgen_model_abi& m, const LinearRequest& request);

/// Everything `linear` prints, at the equilibrium x.
/// `equations`: the derived equations, for the exact Jordan structure (may be null).
LinearReport linear_report(const runtime::Problem& problem, const std::vector<double>& x, const LinearRequest& request,
                           const Equations* equations = nullptr);

void print_linear_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r);
void print_linear_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r);

}  // namespace eomgen::studies
