/// @file The report of `eomgen stability` on an equilibrium of an autonomous model:
/// the equilibrium, M, D, G, K, N, A, eigenvalues and modes, verdict, characteristic
/// polynomial, Hurwitz determinants, theorems, phase plane, symbolic conditions and
/// Lyapunov's critical case, as text or as one JSON object.
#include "studies/stability_report.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::studies {


void print_critical_case(const runtime::CriticalCase& c) {
  if (!c.critical) return;
  std::cout << "  first approximation: inconclusive: eigenvalues on the imaginary axis and none to the right are "
               "Lyapunov's critical case (Hiller §7.5); the nonlinear terms decide\n";
  std::cout << "    energy function: " << c.energy << "\n";
  if (!c.simulation.empty()) std::cout << "    long simulation: " << c.simulation << "\n";
  std::cout << "    nonlinear verdict: " << c.nonlinear_verdict << "\n";
}

void print_stability_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
                const std::optional<StabilityConditions>& conditions) {
  std::string where;
  for (std::size_t i = 0; i < m.num_states; ++i)
    if (i < m.num_coordinates ? !m.is_cyclic[i] : eq.state[i] != 0 || m.is_cyclic[i - m.num_coordinates])
      where += fmt::format("{}{} = {:.9g}", where.empty() ? "" : ", ", m.state_names[i], eq.state[i]);
  std::cout << fmt::format("{}: equilibrium {} (residual {:.2g})\n", m.name, where.empty() ? "at rest" : where, eq.residual);
  std::string state;
  for (const std::string& s : r.state_names) state += (state.empty() ? "" : ", ") + s;
  std::cout << "  reduced state: " << state << "\n";
  if (r.M.size()) {
    std::cout << "  M q'' + (D + G) q' + (K + N) q = B u:\n"
              << matrix_text("M", r.M) << matrix_text("D", r.D) << matrix_text("G", r.G) << matrix_text("K", r.K)
              << matrix_text("N", r.N);
    if (r.B.cols()) std::cout << matrix_text("B", r.B);
  } else {
    std::cout << (m.num_multipliers ? "  x' = A x + B u on the reduced state (the tangent space of the constraint manifold):\n"
                                    : "  x' = A x + B u on the reduced state (Appell's equations, first order in the "
                                      "pseudo-velocities):\n");
    if (r.B_state.cols()) std::cout << matrix_text("B", r.B_state);
  }
  std::cout << matrix_text("A", r.A);
  std::cout << "  eigenvalues and modes:\n";
  for (const runtime::Mode& mode : r.modes)
    std::cout << fmt::format("    {:<28} undamped frequency {:.6g} rad/s, damped frequency {:.6g} rad/s, damping ratio "
                             "{:.6g}\n", complex_text(mode.eigenvalue), mode.undamped_frequency + 0.0, mode.frequency + 0.0,
                             mode.damping_ratio + 0.0);
  if (r.cyclic_zero_eigenvalues)
    std::cout << fmt::format("  {} zero eigenvalue(s) of conserved cyclic momenta left out of the verdict\n",
                             r.cyclic_zero_eigenvalues);
  if (r.quaternion_zero_eigenvalues)
    std::cout << fmt::format("  {} zero eigenvalue(s) of the quaternions' lengths (constant along every motion) left out "
                             "of the verdict\n", r.quaternion_zero_eigenvalues);
  if (r.symmetry_zero_eigenvalues) {
    std::string turns;
    for (const std::string& name : r.symmetry_names) turns += (turns.empty() ? "" : "; ") + name;
    std::cout << fmt::format("  {} zero eigenvalue(s) of turns the equations do not see ({}: each turned equilibrium is "
                             "one too, and the turn's momentum is conserved) left out of the verdict, which is with "
                             "respect to the rest\n", r.symmetry_zero_eigenvalues, turns);
  }
  std::cout << fmt::format("  verdict: {} (stability degree {:.6g})\n", r.verdict, r.stability_degree);
  if (!r.disagreement.empty()) std::cout << "  undecided: " << r.disagreement << "\n";
  std::cout << "  characteristic polynomial: " << polynomial_text(r.characteristic_polynomial) << "\n";
  std::cout << (r.hurwitz_scale == 1.0 ? std::string("  Hurwitz determinants:")
                                        : fmt::format("  Hurwitz determinants (of the polynomial in λ/{:.6g}):", r.hurwitz_scale));
  for (double h : r.hurwitz) std::cout << (std::isnan(h) ? std::string(" lost") : fmt::format(" {:.6g}", h + 0.0));
  std::cout << "\n";
  if (r.hurwitz_ill_conditioned)
    std::cout << fmt::format("  the Hurwitz test is ill-conditioned at order {}: a determinant is lost in rounding; the "
                             "verdict rests on the eigenvalues\n", r.hurwitz.size());
  for (const std::string& t : r.theorems) std::cout << "  theorem: " << t << "\n";
  if (!r.phase_plane.empty()) std::cout << "  phase plane: " << r.phase_plane << "\n";
  if (conditions) {
    std::string kept;
    for (const std::string& k : conditions->kept) kept += (kept.empty() ? "" : ", ") + k;
    std::cout << fmt::format("  stability conditions in {} (parameters taken positive):\n", kept);
    std::cout << "    characteristic polynomial: " << canonical_text(rounded_for_display(conditions->characteristic_polynomial)) << "\n";
    for (const GiNaC::ex& c : conditions->conditions) std::cout << "    " << canonical_text(rounded_for_display(c)) << " > 0\n";
    if (!conditions->vanishing.empty())
      std::cout << "    at best marginal: " << fmt::format("{}", fmt::join(conditions->vanishing, ", "))
                << " vanish(es) identically: the Hurwitz conditions hold for no values of " << kept
                << ", the equilibrium is never asymptotically stable, and the first method decides nothing\n";
    else if (conditions->conditions.empty())
      std::cout << "    none: every Hurwitz condition holds for all positive values of " << kept << "\n";
    for (const GiNaC::ex& c : conditions->equilibrium_equations)
      std::cout << "    where " << canonical_text(rounded_for_display(c)) << " = 0\n";
  }
}

void print_stability_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
                const std::optional<StabilityConditions>& conditions, const runtime::CriticalCase& critical,
                const std::string& extra) {
  std::string equilibrium;
  for (std::size_t i = 0; i < m.num_states; ++i)
    equilibrium += fmt::format("{}{}: {}", equilibrium.empty() ? "" : ", ", json_quoted(m.state_names[i]), json_number(eq.state[i]));
  std::string eigenvalues, modes;
  for (auto l : r.eigenvalues) eigenvalues += (eigenvalues.empty() ? "[" : ", [") + json_number(l.real()) + ", " + json_number(l.imag()) + "]";
  for (const auto& mode : r.modes)
    modes += fmt::format("{}{{\"eigenvalue\": [{}, {}], \"frequency\": {}, \"undamped_frequency\": {}, "
                         "\"damping_ratio\": {}}}", modes.empty() ? "" : ", ", json_number(mode.eigenvalue.real()),
                         json_number(mode.eigenvalue.imag()), json_number(mode.frequency), json_number(mode.undamped_frequency),
                         json_number(mode.damping_ratio));
  std::vector<std::string> condition_texts, equations;
  if (conditions) {
    for (const GiNaC::ex& c : conditions->conditions) condition_texts.push_back(canonical_text(rounded_for_display(c, 12)) + " > 0");
    for (const GiNaC::ex& c : conditions->equilibrium_equations)
      equations.push_back(canonical_text(rounded_for_display(c, 12)) + " = 0");
  }
  std::cout << fmt::format(
      "{{\"model\": \"{}\", \"equilibrium\": {{{}}}, \"residual\": {}, \"state\": {}, \"A\": {}, \"B\": {}, \"M\": {}, "
      "\"D\": {}, \"G\": {}, \"K\": {}, \"N\": {}, \"eigenvalues\": [{}], \"verdict\": \"{}\", \"stability_degree\": {}, "
      "\"cyclic_zero_eigenvalues\": {}, \"quaternion_zero_eigenvalues\": {}, \"symmetry_zero_eigenvalues\": {}, "
      "\"symmetries\": {}, \"modes\": [{}], \"characteristic_polynomial\": {}, \"hurwitz\": {}, \"hurwitz_scale\": {}, \"hurwitz_ill_conditioned\": {}, "
      "\"theorems\": {}, \"phase_plane\": {}, \"conditions\": {}, \"vanishing_conditions\": {}, \"equilibrium_conditions\": {}, "
      "\"disagreement\": {}, \"critical_case\": {}{}}}\n",
      m.name, equilibrium, json_number(eq.residual), json_strings(r.state_names), json_matrix(r.A), json_matrix(r.B_state),
      json_matrix(r.M), json_matrix(r.D), json_matrix(r.G), json_matrix(r.K), json_matrix(r.N), eigenvalues, r.verdict,
      json_number(r.stability_degree), r.cyclic_zero_eigenvalues, r.quaternion_zero_eigenvalues,
      r.symmetry_zero_eigenvalues, json_strings(r.symmetry_names), modes, json_numbers(r.characteristic_polynomial),
      json_numbers(r.hurwitz), json_number(r.hurwitz_scale), r.hurwitz_ill_conditioned ? "true" : "false", json_strings(r.theorems), r.phase_plane.empty() ? "null" : "\"" + r.phase_plane + "\"",
      json_strings(condition_texts), json_strings(conditions ? conditions->vanishing : std::vector<std::string>{}),
      json_strings(equations), r.disagreement.empty() ? "null" : json_quoted(r.disagreement),
      critical.critical ? fmt::format("{{\"first_approximation\": \"inconclusive\", \"energy\": {}, \"simulation\": {}, "
                                      "\"nonlinear_verdict\": \"{}\"}}",
                                      json_quoted(critical.energy), json_quoted(critical.simulation), critical.nonlinear_verdict)
                        : "null",
      extra);
}

}  // namespace eomgen::studies
