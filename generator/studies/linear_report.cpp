#include "studies/linear_report.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "analyse/state_space.hpp"
#include "analyse/system_scales.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/linear_closed_form_output.hpp"
#include "studies/linear_report_sections.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::studies {

namespace {

std::string blocks_text(const std::vector<int>& blocks) {
  std::string out;
  for (int b : blocks) out += (out.empty() ? "" : ", ") + std::to_string(b);
  return "[" + out + "]";
}

std::string shape_json(const eomgen_model_abi& m, const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out += fmt::format("{}{}: {}", i ? ", " : "", json_quoted(m.coordinate_names[i]), json_number(v(i)));
  return "{" + out + "}";
}

// the exact multiplicities and blocks onto the numeric eigenvalues, each matched to its factor
bool apply_exact(const ExactJordan& exact, runtime::JordanStructure& structure) {
  if (exact.factors.empty()) return false;
  for (runtime::EigenvalueStructure& e : structure.eigenvalues) {
    const ExactFactor* best = factor_of(exact, e.value);
    if (!best) return false;
    e.algebraic_multiplicity = best->multiplicity;
    e.jordan_blocks = best->jordan_blocks;
    e.geometric_multiplicity = static_cast<int>(best->jordan_blocks.size());
  }
  structure.uncertain = false;
  return true;
}

}  // namespace

std::string unknown_names(const eomgen_model_abi& m, const LinearRequest& request) {
  std::string unknown;
  auto output_known = [&](const std::string& y) {
    return index_of(m.state_names, m.num_states, y) >= 0 || index_of(m.output_names, m.num_outputs, y) >= 0;
  };
  for (const std::string& y : request.outputs)
    if (!output_known(y)) unknown += (unknown.empty() ? "" : ", ") + y;
  for (const auto& [u, y] : request.transfer) {
    if (index_of(m.input_names, m.num_inputs, u) < 0) unknown += (unknown.empty() ? "" : ", ") + u;
    if (!output_known(y)) unknown += (unknown.empty() ? "" : ", ") + y;
  }
  return unknown;
}

LinearReport linear_report(const runtime::Problem& problem, const std::vector<double>& x, const LinearRequest& request,
                           const Equations* equations) {
  const std::vector<double>& times = request.times;
  const eomgen_model_abi& m = *problem.model;
  std::size_t k = m.num_inputs;
  LinearReport r;
  r.state_names.assign(m.state_names, m.state_names + m.num_states);
  runtime::StateSpace space = runtime::state_space_at(problem, x);
  r.A = space.A, r.B = space.B;
  r.characteristic_polynomial = runtime::polynomial_from_roots(runtime::balanced_eigenvalues(r.A));
  r.system = runtime::analyse_stability(problem, x);
  r.structure = runtime::jordan_structure(r.A);
  if (equations) {
    r.exact = exact_jordan_structure(*equations, problem.parameters, problem.inputs, x);
    r.decided_exactly = apply_exact(r.exact, r.structure);
  }
  r.modes.refusal = runtime::symmetric_problem_refusal(r.system);
  if (r.modes.refusal.empty()) r.modes = runtime::modal_analysis(r.system.M, r.system.D, r.system.K);
  if (equations && !r.modes.modes.empty()) {
    std::vector<std::vector<double>> shapes;
    for (const runtime::NaturalMode& mode : r.modes.modes) shapes.emplace_back(mode.shape.data(), mode.shape.data() + mode.shape.size());
    r.deformed = deformed_shapes(*equations, problem.parameters, problem.inputs, x, shapes);
  }
  r.principal = runtime::principal_coordinates(r.modes, r.system.B, r.A, r.B, r.structure);
  for (double t : times) r.fundamental.push_back({t, runtime::fundamental_matrix(r.A, t)});
  r.input_names.assign(m.input_names, m.input_names + k);
  r.output_names = request.outputs.empty() ? std::vector<std::string>(m.output_names, m.output_names + m.num_outputs)
                                           : request.outputs;
  for (const auto& [u, y] : request.transfer)
    if (std::find(r.output_names.begin(), r.output_names.end(), y) == r.output_names.end()) r.output_names.push_back(y);
  runtime::output_matrices(problem, x, r.output_names, r.C, r.D);
  r.reach = runtime::controllability_and_observability(r.A, r.B, r.C);
  for (const auto& [u, y] : request.transfer) {
    auto i = std::find(r.output_names.begin(), r.output_names.end(), y) - r.output_names.begin();
    r.transfer.push_back({u, y, runtime::transfer_function(r.A, r.B, r.C, r.D, i, index_of(m.input_names, k, u))});
    if (std::find(r.closed_form_outputs.begin(), r.closed_form_outputs.end(), y) == r.closed_form_outputs.end())
      r.closed_form_outputs.push_back(y);
  }
  if (request.symbolic && equations)
    r.closed_form = linear_closed_form(*equations, problem.parameters, problem.inputs, x, r.closed_form_outputs);
  return r;
}


void print_linear_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r) {
  std::string where;
  for (std::size_t i = 0; i < m.num_states; ++i) where += fmt::format("{}{} = {:.9g}", i ? ", " : "", m.state_names[i], eq.state[i]);
  std::cout << fmt::format("{}: linearized about {} (residual {:.2g})\n", m.name, where, eq.residual);
  std::string state;
  for (const std::string& s : r.state_names) state += (state.empty() ? "" : ", ") + s;
  std::cout << "  state x = [" << state << "], x' = A x + B u\n" << matrix_text("A", r.A);
  if (r.B.cols()) std::cout << matrix_text("B", r.B);
  std::cout << "  characteristic polynomial: " << polynomial_text(r.characteristic_polynomial) << "\n";
  if (r.decided_exactly) {
    std::string factors;
    for (const ExactFactor& f : r.exact.factors)
      factors += fmt::format("{}({}){}", factors.empty() ? "" : " * ", canonical_text(f.polynomial),
                             f.multiplicity > 1 ? "^" + std::to_string(f.multiplicity) : "");
    std::cout << "  eigenvalues (multiplicities decided exactly: A is rational, det(lambda I - A) = " << factors << "):\n";
  } else {
    std::cout << fmt::format("  eigenvalues (multiplicities from numerical ranks, singular values below {:.1e} count as zero{}{}):\n",
                             r.structure.rank_tolerance,
                             r.structure.uncertain ? "; UNCERTAIN: a singular value lies near that tolerance, so a nearby "
                                                     "matrix may have another Jordan structure" : "",
                             r.exact.refusal.empty() ? "" : "; not exact: " + r.exact.refusal);
  }
  for (const runtime::EigenvalueStructure& e : r.structure.eigenvalues)
    std::cout << fmt::format("    {:<24} algebraic {}, geometric {}, Jordan blocks {}\n", complex_text(e.value),
                             e.algebraic_multiplicity, e.geometric_multiplicity, blocks_text(e.jordan_blocks));
  if (m.num_quaternions)
    std::cout << fmt::format("  {} of the zero eigenvalues: the length of each quaternion, constant along every motion "
                             "(its eigenvector is the quaternion itself)\n", m.num_quaternions);
  if (!r.modes.refusal.empty()) {
    std::cout << "  natural modes: " << r.modes.refusal << "\n";
  } else {
    std::cout << fmt::format("  natural frequencies and mass-normalized modes (K v = ω² M v), {} rigid-body mode{}:\n",
                             r.modes.rigid_body_modes, r.modes.rigid_body_modes == 1 ? "" : "s");
    for (std::size_t i = 0; i < r.modes.modes.size(); ++i) {
      const runtime::NaturalMode& mode = r.modes.modes[i];
      std::string shape;
      for (Eigen::Index k = 0; k < mode.shape.size(); ++k) shape += fmt::format("{}{} = {:.6g}", k ? ", " : "", m.coordinate_names[k], mode.shape(k));
      if (mode.rigid_body) std::cout << fmt::format("    mode {}: rigid-body (ω = 0); {}\n", i + 1, shape);
      else
        std::cout << fmt::format("    mode {}: ω = {:.9g} rad/s, f = {:.6g} Hz, T = {:.6g} s, damping ratio {:.6g}; {}\n", i + 1,
                                 mode.omega, mode.omega / (2 * M_PI), 2 * M_PI / mode.omega, mode.damping_ratio, shape);
    }
    if (r.modes.damping == "proportional")
      std::cout << fmt::format("  damping: proportional (Rayleigh), D = {:.9g} M + {:.9g} K: the modes decouple exactly\n",
                               r.modes.rayleigh_alpha, r.modes.rayleigh_beta);
    else if (r.modes.damping == "nonproportional")
      std::cout << fmt::format("  damping: not proportional; the largest modal coupling is {:.3g} of the largest modal damping, "
                               "so the damping ratios above are approximations (the eigenvalues of A are exact)\n",
                               r.modes.coupling);
    std::cout << fmt::format("  check: the modes are M-orthonormal to {:.1e}; Rayleigh's quotient of each mode equals its "
                             "omega^2 to {:.1e} (Hiller §8.1.4)\n", r.modes.orthonormality_error, r.modes.rayleigh_error);
    for (const runtime::ModalAnalysis::Constrained& c : r.modes.constrained) {
      std::string omegas;
      for (double w : c.omegas) omegas += (omegas.empty() ? "" : ", ") + fmt::format("{:.6g}", w);
      std::cout << fmt::format("  check: with {} held at 0 the frequencies are {} rad/s: {}\n", m.coordinate_names[c.fixed], omegas,
                               c.interlaces ? "they interlace the free system's, as a constraint must"
                                            : "they do NOT interlace the free system's (a bug: please report it)");
    }
  }
  if (r.principal.kind == "none") {
    std::cout << "  principal coordinates: " << r.principal.reason << "\n";
  } else {
    const std::string& kind = r.principal.kind;
    std::cout << (kind == "modal"          ? "  principal coordinates q = Phi eta, Phi the modes above (Hiller §6.3), decoupled:\n"
                  : kind == "eigenvectors" ? "  principal coordinates x = V eta, V the eigenvectors of A (Hiller §6.3), decoupled:\n"
                                           : fmt::format("  principal coordinates x = V eta, V the Jordan chains of A (generalized "
                                                         "eigenvectors, Hiller §6.3; |AV - VJ| = {:.1e} of its terms, A "
                                                         "balanced), coupled only along each chain:\n",
                                                         r.principal.jordan_residual));
    for (const std::string& line : principal_equations(r)) std::cout << "    " << line << "\n";
  }
  for (const auto& [t, Phi] : r.fundamental) std::cout << matrix_text(fmt::format("Phi({:g})", t).c_str(), Phi);
  print_reach_text(m, r);
  print_closed_form_text(r);
  if (r.A.rows() == 2)
    std::cout << "  phase plane: " << runtime::phase_plane_type(r.A) << " (Hiller §7.7; see `eomgen stability`)\n";
}

void print_linear_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r) {
  std::string equilibrium, eigenvalues, modes, fundamental;
  for (std::size_t i = 0; i < m.num_states; ++i)
    equilibrium += fmt::format("{}{}: {}", i ? ", " : "", json_quoted(m.state_names[i]), json_number(eq.state[i]));
  for (const runtime::EigenvalueStructure& e : r.structure.eigenvalues)
    eigenvalues += fmt::format("{}{{\"re\": {}, \"im\": {}, \"algebraic_multiplicity\": {}, \"geometric_multiplicity\": {}, "
                               "\"jordan_blocks\": {}}}", eigenvalues.empty() ? "" : ", ", json_number(e.value.real()),
                               json_number(e.value.imag()), e.algebraic_multiplicity, e.geometric_multiplicity,
                               blocks_text(e.jordan_blocks));
  for (const runtime::NaturalMode& mode : r.modes.modes)
    modes += fmt::format("{}{{\"frequency_rad_s\": {}, \"frequency_hz\": {}, \"period_s\": {}, \"damping_ratio\": {}, "
                         "\"rigid_body\": {}, \"shape\": {}, \"normalization\": \"mass\"}}", modes.empty() ? "" : ", ",
                         json_number(mode.omega), json_number(mode.omega / (2 * M_PI)),
                         mode.rigid_body ? "null" : json_number(2 * M_PI / mode.omega), json_number(mode.damping_ratio),
                         mode.rigid_body ? "true" : "false", shape_json(m, mode.shape));
  for (const auto& [t, Phi] : r.fundamental)
    fundamental += fmt::format("{}{{\"t\": {}, \"matrix\": {}}}", fundamental.empty() ? "" : ", ", json_number(t), json_matrix(Phi));
  std::cout << fmt::format(
      "{{\"model\": {}, \"equilibrium\": {{{}}}, \"state\": {}, \"A\": {}, \"B\": {}, \"characteristic_polynomial\": {}, "
      "\"eigenvalues\": [{}], \"jordan_decided\": \"{}\", \"rank_tolerance\": {}, \"structure_uncertain\": {}, \"modes\": [{}], \"rigid_body_modes\": {}, "
      "\"modal_refusal\": {}, \"damping\": {{\"kind\": \"{}\", \"rayleigh_alpha\": {}, \"rayleigh_beta\": {}, \"coupling\": {}}}, "
      "\"orthonormality_error\": {}, \"fundamental_matrix\": [{}]{}{}}}\n",
      json_quoted(m.name), equilibrium, json_strings(r.state_names), json_matrix(r.A), json_matrix(r.B),
      json_numbers(r.characteristic_polynomial), eigenvalues, r.decided_exactly ? "exact" : "numeric",
      json_number(r.structure.rank_tolerance), r.structure.uncertain ? "true" : "false", modes, r.modes.rigid_body_modes,
      r.modes.refusal.empty() ? "null" : json_quoted(r.modes.refusal), r.modes.damping,
      json_number(r.modes.rayleigh_alpha), json_number(r.modes.rayleigh_beta), json_number(r.modes.coupling),
      json_number(r.modes.orthonormality_error), fundamental, reach_json(m, r), closed_form_json(r));
}

}  // namespace eomgen::studies
