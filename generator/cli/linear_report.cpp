#include "cli/linear_report.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/report_text.hpp"

namespace eomgen::cli {

namespace {

// the symmetric problem K v = ω² M v describes the motion only without gyroscopic and
// circulatory forces (Hiller §8.1); the eigenvalues of A do in every case
std::string modal_refusal(const runtime::StabilityReport& s) {
  if (s.M.size() == 0) return "the model is in first-order form (Appell or Hamilton): its modes are the eigenvalues of A";
  double scale = std::max(1.0, s.K.cwiseAbs().maxCoeff() + s.D.cwiseAbs().maxCoeff());
  if (s.G.size() && s.G.cwiseAbs().maxCoeff() > 1e-12 * scale)
    return "gyroscopic forces G couple the coordinates: the modes are the eigenvalues of A";
  if (s.N.size() && s.N.cwiseAbs().maxCoeff() > 1e-12 * scale)
    return "circulatory forces N are not conservative: the modes are the eigenvalues of A";
  return "";
}

std::string blocks_text(const std::vector<int>& blocks) {
  std::string out;
  for (int b : blocks) out += (out.empty() ? "" : ", ") + std::to_string(b);
  return "[" + out + "]";
}

std::string shape_json(const eomgen_model_abi& m, const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out += fmt::format("{}\"{}\": {}", i ? ", " : "", json_escape(m.coordinate_names[i]), number(v(i)));
  return "{" + out + "}";
}

}  // namespace

// det(λI − A) = Π (λ − λ_i), expanded; real up to rounding
std::vector<double> characteristic_polynomial(const Eigen::MatrixXd& A) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(A, false);
  std::vector<std::complex<double>> c{1.0};
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    std::complex<double> root = solver.eigenvalues()(i);
    c.push_back(0.0);
    for (std::size_t k = c.size() - 1; k > 0; --k) c[k] -= root * c[k - 1];
  }
  std::vector<double> real;
  for (const auto& z : c) real.push_back(z.real());
  return real;
}

LinearReport linear_report(const runtime::Problem& problem, const std::vector<double>& x, const std::vector<double>& times) {
  const eomgen_model_abi& m = *problem.model;
  std::size_t N = m.num_states, k = m.num_inputs;
  LinearReport r;
  r.state_names.assign(m.state_names, m.state_names + N);
  // at an equilibrium or steady motion (q'' = 0) the Jacobian of the right-hand side is A exactly
  Eigen::Matrix<double, -1, -1, Eigen::RowMajor> J(N, N), B(N, std::max<std::size_t>(k, 1));
  const double* u = problem.inputs.empty() ? nullptr : problem.inputs.data();
  m.jacobian_state(0.0, x.data(), u, problem.parameters.data(), J.data());
  m.jacobian_input(0.0, x.data(), u, problem.parameters.data(), B.data());
  r.A = J;
  r.B = Eigen::MatrixXd(B).leftCols(static_cast<Eigen::Index>(k));
  r.characteristic_polynomial = characteristic_polynomial(r.A);
  r.system = runtime::analyse_stability(problem, x);
  r.structure = runtime::jordan_structure(r.A);
  r.modes.refusal = modal_refusal(r.system);
  if (r.modes.refusal.empty()) r.modes = runtime::modal_analysis(r.system.M, r.system.D, r.system.K);
  for (double t : times) r.fundamental.push_back({t, runtime::fundamental_matrix(r.A, t)});
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
  std::cout << fmt::format("  eigenvalues (multiplicities from numerical ranks, singular values below {:.1e} count as zero{}):\n",
                           r.structure.rank_tolerance,
                           r.structure.uncertain ? "; UNCERTAIN: a singular value lies near that tolerance, so a nearby "
                                                   "matrix may have another Jordan structure" : "");
  for (const runtime::EigenvalueStructure& e : r.structure.eigenvalues)
    std::cout << fmt::format("    {:<24} algebraic {}, geometric {}, Jordan blocks {}\n", complex_text(e.value),
                             e.algebraic_multiplicity, e.geometric_multiplicity, blocks_text(e.jordan_blocks));
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
    std::cout << fmt::format("  check: the modes are M-orthonormal to {:.1e}\n", r.modes.orthonormality_error);
  }
  for (const auto& [t, Phi] : r.fundamental) std::cout << matrix_text(fmt::format("Phi({:g})", t).c_str(), Phi);
  if (r.A.rows() == 2)
    std::cout << "  phase plane: " << runtime::phase_plane_type(r.A) << " (Hiller §7.7; see `eomgen stability`)\n";
}

void print_linear_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const LinearReport& r) {
  std::string equilibrium, eigenvalues, modes, fundamental;
  for (std::size_t i = 0; i < m.num_states; ++i)
    equilibrium += fmt::format("{}\"{}\": {}", i ? ", " : "", json_escape(m.state_names[i]), number(eq.state[i]));
  for (const runtime::EigenvalueStructure& e : r.structure.eigenvalues)
    eigenvalues += fmt::format("{}{{\"re\": {}, \"im\": {}, \"algebraic_multiplicity\": {}, \"geometric_multiplicity\": {}, "
                               "\"jordan_blocks\": {}}}", eigenvalues.empty() ? "" : ", ", number(e.value.real()),
                               number(e.value.imag()), e.algebraic_multiplicity, e.geometric_multiplicity,
                               blocks_text(e.jordan_blocks));
  for (const runtime::NaturalMode& mode : r.modes.modes)
    modes += fmt::format("{}{{\"frequency_rad_s\": {}, \"frequency_hz\": {}, \"period_s\": {}, \"damping_ratio\": {}, "
                         "\"rigid_body\": {}, \"shape\": {}, \"normalization\": \"mass\"}}", modes.empty() ? "" : ", ",
                         number(mode.omega), number(mode.omega / (2 * M_PI)),
                         mode.rigid_body ? "null" : number(2 * M_PI / mode.omega), number(mode.damping_ratio),
                         mode.rigid_body ? "true" : "false", shape_json(m, mode.shape));
  for (const auto& [t, Phi] : r.fundamental)
    fundamental += fmt::format("{}{{\"t\": {}, \"matrix\": {}}}", fundamental.empty() ? "" : ", ", number(t), json_matrix(Phi));
  std::cout << fmt::format(
      "{{\"model\": \"{}\", \"equilibrium\": {{{}}}, \"state\": {}, \"A\": {}, \"B\": {}, \"characteristic_polynomial\": {}, "
      "\"eigenvalues\": [{}], \"rank_tolerance\": {}, \"structure_uncertain\": {}, \"modes\": [{}], \"rigid_body_modes\": {}, "
      "\"modal_refusal\": {}, \"damping\": {{\"kind\": \"{}\", \"rayleigh_alpha\": {}, \"rayleigh_beta\": {}, \"coupling\": {}}}, "
      "\"orthonormality_error\": {}, \"fundamental_matrix\": [{}]}}\n",
      json_escape(m.name), equilibrium, json_strings(r.state_names), json_matrix(r.A), json_matrix(r.B),
      json_numbers(r.characteristic_polynomial), eigenvalues,
      number(r.structure.rank_tolerance), r.structure.uncertain ? "true" : "false", modes, r.modes.rigid_body_modes,
      r.modes.refusal.empty() ? "null" : "\"" + json_escape(r.modes.refusal) + "\"", r.modes.damping,
      number(r.modes.rayleigh_alpha), number(r.modes.rayleigh_beta), number(r.modes.coupling),
      number(r.modes.orthonormality_error), fundamental);
}

}  // namespace eomgen::cli
