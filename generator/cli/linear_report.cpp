#include "cli/linear_report.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/linear_report_sections.hpp"
#include "cli/report_text.hpp"
#include "symbolic/canonical_print.hpp"

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

int name_index(const char* const* names, std::size_t count, const std::string& name) {
  for (std::size_t i = 0; i < count; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

// C and D: a state is read exactly; a model output is differentiated centrally (h = 1e-6
// times the size of the variable, error about 1e-10 relative)
void output_matrices(const runtime::Problem& p, const std::vector<double>& x, LinearReport& r) {
  const eomgen_model_abi& m = *p.model;
  std::size_t N = m.num_states, k = m.num_inputs, q = r.output_names.size();
  r.C = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(N));
  r.D = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(k));
  std::vector<double> u = p.inputs, y_plus(m.num_outputs + 1), y_minus(m.num_outputs + 1);
  auto outputs_at = [&](const std::vector<double>& xs, const std::vector<double>& us, std::vector<double>& y) {
    m.outputs(0.0, xs.data(), us.empty() ? nullptr : us.data(), p.parameters.data(), y.data());
  };
  for (std::size_t i = 0; i < q; ++i) {
    Eigen::Index row = static_cast<Eigen::Index>(i);
    if (int s = name_index(m.state_names, N, r.output_names[i]); s >= 0) {
      r.C(row, s) = 1;
      continue;
    }
    int o = name_index(m.output_names, m.num_outputs, r.output_names[i]);
    for (std::size_t j = 0; j < N + k; ++j) {
      std::vector<double> xp = x, xm = x, up = u, um = u;
      double& plus = j < N ? xp[j] : up[j - N];
      double& minus = j < N ? xm[j] : um[j - N];
      double h = 1e-6 * std::max(1.0, std::abs(plus));
      plus += h, minus -= h;
      outputs_at(xp, up, y_plus), outputs_at(xm, um, y_minus);
      double slope = (y_plus[o] - y_minus[o]) / (2 * h);
      (j < N ? r.C(row, static_cast<Eigen::Index>(j)) : r.D(row, static_cast<Eigen::Index>(j - N))) = slope;
    }
  }
}

}  // namespace

std::string unknown_names(const eomgen_model_abi& m, const LinearRequest& request) {
  std::string unknown;
  auto output_known = [&](const std::string& y) {
    return name_index(m.state_names, m.num_states, y) >= 0 || name_index(m.output_names, m.num_outputs, y) >= 0;
  };
  for (const std::string& y : request.outputs)
    if (!output_known(y)) unknown += (unknown.empty() ? "" : ", ") + y;
  for (const auto& [u, y] : request.transfer) {
    if (name_index(m.input_names, m.num_inputs, u) < 0) unknown += (unknown.empty() ? "" : ", ") + u;
    if (!output_known(y)) unknown += (unknown.empty() ? "" : ", ") + y;
  }
  return unknown;
}

namespace {

// |f(λ)| relative to the size of its terms
double residual_at(const ExactFactor& f, const GiNaC::symbol& lambda, std::complex<double> z) {
  std::complex<double> sum = 0;
  double size = 0;
  for (int k = 0; k <= f.degree; ++k) {
    GiNaC::numeric c = GiNaC::ex_to<GiNaC::numeric>(f.polynomial.coeff(lambda, k).evalf());
    std::complex<double> term = c.to_double() * std::pow(z, k);
    sum += term, size += std::abs(term);
  }
  return std::abs(sum) / std::max(size, 1e-300);
}

// the exact multiplicities and blocks onto the numeric eigenvalues, each matched to its factor
bool apply_exact(const ExactJordan& exact, runtime::JordanStructure& structure) {
  if (exact.factors.empty()) return false;
  for (runtime::EigenvalueStructure& e : structure.eigenvalues) {
    const ExactFactor* best = nullptr;
    double smallest = INFINITY;
    for (const ExactFactor& f : exact.factors)
      if (double r = residual_at(f, exact.lambda, e.value); r < smallest) smallest = r, best = &f;
    if (!best || smallest > 1e-6) return false;
    e.algebraic_multiplicity = best->multiplicity;
    e.jordan_blocks = best->jordan_blocks;
    e.geometric_multiplicity = static_cast<int>(best->jordan_blocks.size());
  }
  structure.uncertain = false;
  return true;
}

}  // namespace

LinearReport linear_report(const runtime::Problem& problem, const std::vector<double>& x, const LinearRequest& request,
                           const Equations* equations) {
  const std::vector<double>& times = request.times;
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
  if (equations) {
    r.exact = exact_jordan_structure(*equations, problem.parameters, problem.inputs, x);
    r.decided_exactly = apply_exact(r.exact, r.structure);
  }
  r.modes.refusal = modal_refusal(r.system);
  if (r.modes.refusal.empty()) r.modes = runtime::modal_analysis(r.system.M, r.system.D, r.system.K);
  r.principal = runtime::principal_coordinates(r.modes, r.system.B, r.A, r.B, r.structure);
  for (double t : times) r.fundamental.push_back({t, runtime::fundamental_matrix(r.A, t)});
  r.input_names.assign(m.input_names, m.input_names + k);
  r.output_names = request.outputs.empty() ? std::vector<std::string>(m.output_names, m.output_names + m.num_outputs)
                                           : request.outputs;
  for (const auto& [u, y] : request.transfer)
    if (std::find(r.output_names.begin(), r.output_names.end(), y) == r.output_names.end()) r.output_names.push_back(y);
  output_matrices(problem, x, r);
  r.reach = runtime::controllability_and_observability(r.A, r.B, r.C);
  for (const auto& [u, y] : request.transfer) {
    auto i = std::find(r.output_names.begin(), r.output_names.end(), y) - r.output_names.begin();
    r.transfer.push_back({u, y, runtime::transfer_function(r.A, r.B, r.C, r.D, i, name_index(m.input_names, k, u))});
  }
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
    std::cout << (r.principal.kind == "modal" ? "  principal coordinates q = Phi eta, Phi the modes above (Hiller §6.3), decoupled:\n"
                                              : "  principal coordinates x = V eta, V the eigenvectors of A (Hiller §6.3), decoupled:\n");
    for (const std::string& line : principal_equations(r)) std::cout << "    " << line << "\n";
  }
  for (const auto& [t, Phi] : r.fundamental) std::cout << matrix_text(fmt::format("Phi({:g})", t).c_str(), Phi);
  print_reach_text(m, r);
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
      "\"eigenvalues\": [{}], \"jordan_decided\": \"{}\", \"rank_tolerance\": {}, \"structure_uncertain\": {}, \"modes\": [{}], \"rigid_body_modes\": {}, "
      "\"modal_refusal\": {}, \"damping\": {{\"kind\": \"{}\", \"rayleigh_alpha\": {}, \"rayleigh_beta\": {}, \"coupling\": {}}}, "
      "\"orthonormality_error\": {}, \"fundamental_matrix\": [{}]{}}}\n",
      json_escape(m.name), equilibrium, json_strings(r.state_names), json_matrix(r.A), json_matrix(r.B),
      json_numbers(r.characteristic_polynomial), eigenvalues, r.decided_exactly ? "exact" : "numeric",
      number(r.structure.rank_tolerance), r.structure.uncertain ? "true" : "false", modes, r.modes.rigid_body_modes,
      r.modes.refusal.empty() ? "null" : "\"" + json_escape(r.modes.refusal) + "\"", r.modes.damping,
      number(r.modes.rayleigh_alpha), number(r.modes.rayleigh_beta), number(r.modes.coupling),
      number(r.modes.orthonormality_error), fundamental, reach_json(m, r));
}

}  // namespace eomgen::cli
