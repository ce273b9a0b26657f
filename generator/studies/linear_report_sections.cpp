#include "studies/linear_report_sections.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"

namespace eomgen::studies {

namespace {

std::vector<std::string> states_named(const eomgen_model_abi& m, const Eigen::VectorXcd& direction) {
  std::vector<std::string> names;
  if (direction.size() == 0) return names;
  double largest = direction.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < direction.size(); ++i)
    if (std::abs(direction(i)) >= 0.1 * largest) names.push_back(m.state_names[i]);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// "c1 F + c2 G", or "0" without inputs
std::string input_terms(const LinearReport& r, const std::vector<std::complex<double>>& row) {
  std::string out;
  for (std::size_t j = 0; j < row.size(); ++j)
    if (std::abs(row[j]) > 0) out += fmt::format("{}({}) {}", out.empty() ? "" : " + ", complex_text(row[j]), r.input_names[j]);
  return out.empty() ? "0" : out;
}

std::string roots_text(const std::vector<std::complex<double>>& roots) {
  std::string out;
  for (const auto& z : roots) out += (out.empty() ? "" : ", ") + complex_text(z);
  return out.empty() ? "(none)" : out;
}

std::string roots_json(const std::vector<std::complex<double>>& roots) {
  std::string out;
  for (const auto& z : roots) out += fmt::format("{}[{}, {}]", out.empty() ? "" : ", ", json_number(z.real()), json_number(z.imag()));
  return "[" + out + "]";
}

}  // namespace

// one per principal coordinate η_i (Hiller §6.3)
std::vector<std::string> principal_equations(const LinearReport& r) {
  std::vector<std::string> out;
  const runtime::PrincipalCoordinates& p = r.principal;
  if (p.kind == "modal") {
    for (std::size_t i = 0; i < r.modes.modes.size(); ++i) {
      const runtime::NaturalMode& mode = r.modes.modes[i];
      std::vector<std::complex<double>> row;
      for (Eigen::Index j = 0; j < p.modal_inputs.cols(); ++j) row.push_back(p.modal_inputs(Eigen::Index(i), j));
      out.push_back(fmt::format("der(der(eta{0})) + {1:.9g}*der(eta{0}) + {2:.9g}*eta{0} = {3}", i + 1,
                                2 * mode.damping_ratio * mode.omega, mode.omega * mode.omega, input_terms(r, row)));
    }
  } else if (p.kind == "eigenvectors" || p.kind == "jordan") {
    for (std::size_t i = 0; i < p.eigenvalues.size(); ++i) {
      std::vector<std::complex<double>> row;
      for (Eigen::Index j = 0; j < p.eigen_inputs.cols(); ++j) row.push_back(p.eigen_inputs(Eigen::Index(i), j));
      bool chained = p.kind == "jordan" && p.chained[i];
      out.push_back(fmt::format("der(eta{0}) = ({1})*eta{0} + {2}{3}", i + 1, complex_text(p.eigenvalues[i]),
                                chained ? fmt::format("eta{} + ", i + 2) : "", input_terms(r, row)));
    }
  }
  return out;
}

void print_reach_text(const eomgen_model_abi& m, const LinearReport& r) {
  std::size_t n = m.num_states;
  if (!r.input_names.empty())
    std::cout << fmt::format("  controllability from {}: {} (Kalman rank {} of {})\n", joined(r.input_names),
                             r.reach.controllable ? "controllable" : "NOT controllable", r.reach.kalman_controllability_rank, n);
  if (!r.output_names.empty())
    std::cout << fmt::format("  observability from {}: {} (Kalman rank {} of {})\n", joined(r.output_names),
                             r.reach.observable ? "observable" : "NOT observable", r.reach.kalman_observability_rank, n);
  for (const runtime::ModeReach& mode : r.reach.modes) {
    if (!r.input_names.empty() && !mode.controllable)
      std::cout << fmt::format("    the mode {} cannot be reached by the inputs (PBH); it lives in {}\n",
                               complex_text(mode.eigenvalue), joined(states_named(m, mode.unreachable)));
    if (!r.output_names.empty() && !mode.observable)
      std::cout << fmt::format("    the mode {} cannot be seen in the outputs (PBH); it moves {}\n",
                               complex_text(mode.eigenvalue), joined(states_named(m, mode.unseen)));
  }
  for (const LinearReport::Pair& p : r.transfer) {
    if (p.g.constant()) {
      std::cout << fmt::format("  transfer function {} -> {}: G(s) = {:.9g} identically ({})\n", p.input, p.output, p.g.d,
                               p.g.d == 0 ? "the output does not see the input" : "a direct feedthrough only");
      continue;
    }
    std::complex<double> dc = p.g.dc_gain();
    std::cout << fmt::format("  transfer function {} -> {}: G(s) = {:.9g} * prod(s - zeros) / prod(s - poles)\n", p.input,
                             p.output, p.g.gain);
    if (p.g.removed_modes > 0)
      std::cout << fmt::format("    (minimal realization: {} mode(s) that the input does not reach or the output does not "
                               "see cancel)\n", p.g.removed_modes);
    std::cout << fmt::format("    poles: {}\n    zeros: {}\n    G(0) = {}\n", roots_text(p.g.poles), roots_text(p.g.zeros),
                             std::isfinite(std::abs(dc)) ? complex_text(dc) : "infinite (a pole at 0)");
  }
}

std::string reach_json(const eomgen_model_abi& m, const LinearReport& r) {
  std::string modes, transfer;
  for (const runtime::ModeReach& mode : r.reach.modes)
    modes += fmt::format("{}{{\"re\": {}, \"im\": {}, \"controllable\": {}, \"observable\": {}, \"unreachable_states\": {}, "
                         "\"unseen_states\": {}}}", modes.empty() ? "" : ", ", json_number(mode.eigenvalue.real()),
                         json_number(mode.eigenvalue.imag()), mode.controllable ? "true" : "false", mode.observable ? "true" : "false",
                         json_strings(states_named(m, mode.unreachable)), json_strings(states_named(m, mode.unseen)));
  for (const LinearReport::Pair& p : r.transfer) {
    std::complex<double> dc = p.g.dc_gain();
    transfer += fmt::format("{}{{\"input\": {}, \"output\": {}, \"poles\": {}, \"zeros\": {}, \"gain\": {}, "
                            "\"dc_gain\": {}, \"cancelled_modes\": {}, \"constant\": {}}}", transfer.empty() ? "" : ", ",
                            json_quoted(p.input), json_quoted(p.output), roots_json(p.g.poles), roots_json(p.g.zeros),
                            json_number(p.g.gain), std::abs(dc.imag()) < 1e-12 * std::abs(dc) ? json_number(dc.real()) : "null",
                            p.g.removed_modes, p.g.constant() ? "true" : "false");
  }
  std::string constrained;
  for (const runtime::ModalAnalysis::Constrained& c : r.modes.constrained) {
    std::vector<double> omegas = c.omegas;
    constrained += fmt::format("{}{{\"fixed\": {}, \"frequencies_rad_s\": {}, \"interlaces\": {}}}",
                               constrained.empty() ? "" : ", ", json_quoted(m.coordinate_names[c.fixed]), json_numbers(omegas),
                               c.interlaces ? "true" : "false");
  }
  std::string bounds = fmt::format(", \"rayleigh_quotient_error\": {}, \"interlacing\": [{}]", json_number(r.modes.rayleigh_error),
                                   constrained);
  const runtime::PrincipalCoordinates& p = r.principal;
  std::string principal = fmt::format(", \"principal_coordinates\": {{\"kind\": \"{}\", \"reason\": {}, \"matrix\": {}, \"equations\": {}}}",
                                      p.kind, p.reason.empty() ? "null" : json_quoted(p.reason),
                                      p.kind == "modal" ? json_matrix(p.modal_matrix) : "null", json_strings(principal_equations(r)));
  return bounds + principal + fmt::format(", \"inputs\": {}, \"outputs\": {}, \"C\": {}, \"D\": {}, \"controllable\": {}, \"observable\": {}, "
                     "\"kalman_ranks\": {{\"controllability\": {}, \"observability\": {}}}, \"mode_reach\": [{}], "
                     "\"transfer_functions\": [{}]", json_strings(r.input_names), json_strings(r.output_names),
                     json_matrix(r.C), json_matrix(r.D), r.reach.controllable ? "true" : "false",
                     r.reach.observable ? "true" : "false", r.reach.kalman_controllability_rank,
                     r.reach.kalman_observability_rank, modes, transfer);
}

}  // namespace eomgen::studies
