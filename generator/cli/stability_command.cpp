/// @file `eomgen stability`: the equilibrium, its linearization split by force
/// type, eigenvalues, verdict, modes, Hurwitz test, the classical theorems that
/// apply, and with --symbolic the stability conditions in the parameters.
#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/critical_case.hpp"
#include "analyse/equilibrium.hpp"
#include "analyse/linear_stability.hpp"
#include "analyse/stability_conditions.hpp"
#include "analyse/state_check.hpp"
#include "cli/commands.hpp"
#include "cli/loaded_model.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::cli {

namespace {

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v + 0.0) : "null"; }

std::string json_matrix(const Eigen::MatrixXd& A) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < A.cols(); ++j) out += (j ? ", " : "") + number(A(i, j));
    out += "]";
  }
  return out + "]";
}

std::string json_strings(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "\"" : ", \"") + json_escape(s) + "\"";
  return "[" + out + "]";
}

std::string json_numbers(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += (out.empty() ? "" : ", ") + number(x);
  return "[" + out + "]";
}

std::string complex_text(std::complex<double> z) {
  z += std::complex<double>(0.0, 0.0);  // no "-0"
  if (std::abs(z.real()) <= 1e-12 * std::abs(z)) z.real(0.0);  // on the axis within rounding
  if (std::abs(z.imag()) <= 1e-12 * std::abs(z)) z.imag(0.0);
  if (std::abs(z.imag()) < 1e-300) return fmt::format("{:.6g}", z.real());
  return fmt::format("{:.6g} {} {:.6g}i", z.real(), z.imag() < 0 ? "-" : "+", std::abs(z.imag()));
}

std::string matrix_text(const char* name, const Eigen::MatrixXd& A) {
  std::ostringstream s;
  s << "  " << name << " =\n";
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    s << "   ";
    for (Eigen::Index j = 0; j < A.cols(); ++j) s << fmt::format(" {:>12.6g}", A(i, j) + 0.0);
    s << "\n";
  }
  return s.str();
}

std::string polynomial_text(const std::vector<double>& c) {
  std::string out;
  int n = static_cast<int>(c.size()) - 1;
  for (int k = 0; k <= n; ++k) {
    int power = n - k;
    std::string term = fmt::format("{:.6g}", std::abs(c[k])) + (power > 1 ? fmt::format(" λ^{}", power) : power == 1 ? " λ" : "");
    out += out.empty() ? (c[k] < 0 ? "-" + term : term) : (c[k] < 0 ? " - " : " + ") + term;
  }
  return out;
}

struct Options {
  std::string model;
  std::vector<std::string> at, sets;
  std::string symbolic;
  double period = 0;
  bool json = false;
};

// the state an --at list names: given values, other coordinates as in the model, other velocities zero
std::optional<std::vector<double>> state_from_at(const eomgen_model_abi& m, const std::vector<double>& initial,
                                                 const std::vector<std::string>& at) {
  std::vector<double> x = initial;
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) x[i] = 0;
  if (!assign_states(m, at, "--at", x)) return std::nullopt;
  return x;
}

std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream s(list);
  for (std::string name; std::getline(s, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

void print_critical_case(const runtime::CriticalCase& c) {
  if (!c.critical) return;
  std::cout << "  first approximation: inconclusive: eigenvalues on the imaginary axis and none to the right are "
               "Lyapunov's critical case (Hiller §7.5); the nonlinear terms decide\n";
  std::cout << "    energy function: " << c.energy << "\n";
  if (!c.simulation.empty()) std::cout << "    long simulation: " << c.simulation << "\n";
  std::cout << "    nonlinear verdict: " << c.nonlinear_verdict << "\n";
}

void print_text(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
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
    std::cout << "  x' = A x + B u on the reduced state (Appell's equations, first order in the pseudo-velocities):\n";
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
  std::cout << fmt::format("  verdict: {} (stability degree {:.6g})\n", r.verdict, r.stability_degree);
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
    if (conditions->conditions.empty())
      std::cout << "    none: every Hurwitz condition holds for all positive values of " << kept << "\n";
    for (const GiNaC::ex& c : conditions->equilibrium_equations)
      std::cout << "    where " << canonical_text(rounded_for_display(c)) << " = 0\n";
  }
}

void print_json(const eomgen_model_abi& m, const runtime::Equilibrium& eq, const runtime::StabilityReport& r,
                const std::optional<StabilityConditions>& conditions, const runtime::CriticalCase& critical) {
  std::string equilibrium;
  for (std::size_t i = 0; i < m.num_states; ++i)
    equilibrium += fmt::format("{}\"{}\": {}", equilibrium.empty() ? "" : ", ", json_escape(m.state_names[i]), number(eq.state[i]));
  std::string eigenvalues, modes;
  for (auto l : r.eigenvalues) eigenvalues += (eigenvalues.empty() ? "[" : ", [") + number(l.real()) + ", " + number(l.imag()) + "]";
  for (const auto& mode : r.modes)
    modes += fmt::format("{}{{\"eigenvalue\": [{}, {}], \"frequency\": {}, \"undamped_frequency\": {}, "
                         "\"damping_ratio\": {}}}", modes.empty() ? "" : ", ", number(mode.eigenvalue.real()),
                         number(mode.eigenvalue.imag()), number(mode.frequency), number(mode.undamped_frequency),
                         number(mode.damping_ratio));
  std::vector<std::string> condition_texts, equations;
  if (conditions) {
    for (const GiNaC::ex& c : conditions->conditions) condition_texts.push_back(canonical_text(rounded_for_display(c, 12)) + " > 0");
    for (const GiNaC::ex& c : conditions->equilibrium_equations)
      equations.push_back(canonical_text(rounded_for_display(c, 12)) + " = 0");
  }
  std::cout << fmt::format(
      "{{\"model\": \"{}\", \"equilibrium\": {{{}}}, \"residual\": {}, \"state\": {}, \"A\": {}, \"B\": {}, \"M\": {}, "
      "\"D\": {}, \"G\": {}, \"K\": {}, \"N\": {}, \"eigenvalues\": [{}], \"verdict\": \"{}\", \"stability_degree\": {}, "
      "\"cyclic_zero_eigenvalues\": {}, \"modes\": [{}], \"characteristic_polynomial\": {}, \"hurwitz\": {}, \"hurwitz_scale\": {}, \"hurwitz_ill_conditioned\": {}, "
      "\"theorems\": {}, \"phase_plane\": {}, \"conditions\": {}, \"equilibrium_conditions\": {}, \"critical_case\": {}}}\n",
      m.name, equilibrium, number(eq.residual), json_strings(r.state_names), json_matrix(r.A), json_matrix(r.B_state),
      json_matrix(r.M), json_matrix(r.D), json_matrix(r.G), json_matrix(r.K), json_matrix(r.N), eigenvalues, r.verdict,
      number(r.stability_degree), r.cyclic_zero_eigenvalues, modes, json_numbers(r.characteristic_polynomial),
      json_numbers(r.hurwitz), number(r.hurwitz_scale), r.hurwitz_ill_conditioned ? "true" : "false", json_strings(r.theorems), r.phase_plane.empty() ? "null" : "\"" + r.phase_plane + "\"",
      json_strings(condition_texts), json_strings(equations),
      critical.critical ? fmt::format("{{\"first_approximation\": \"inconclusive\", \"energy\": \"{}\", \"simulation\": \"{}\", "
                                      "\"nonlinear_verdict\": \"{}\"}}",
                                      json_escape(critical.energy), json_escape(critical.simulation), critical.nonlinear_verdict)
                        : "null");
}

}  // namespace

std::optional<int> stability_refusal(const LoadedProblem& loaded, const std::string& model, bool symbolic) {
  if (loaded.equations.has_multipliers) {
    std::cerr << fmt::format("eomgen: error: {} is a Lagrange I model: its coordinates are not independent, and the "
                             "constraint directions would show as spurious eigenvalues\n  hint: derive it with method = "
                             "\"appell\" (independent pseudo-velocities) for a stability analysis\n", model);
    return exit_user_error;
  }
  if (symbolic && loaded.equations.uses_pseudo_velocities()) {
    std::cerr << "eomgen: error: symbolic stability conditions need the second-order form M q'' + P q' + Q q; Appell "
                 "models are analysed numerically (leave out --symbolic)\n";
    return exit_user_error;
  }
  return std::nullopt;
}

// a state where M or f is not finite, or M is singular, has no meaningful linearization
std::optional<int> refuse_unfit(const runtime::Problem& problem, const std::vector<double>& x, const char* which) {
  std::string why = runtime::unfit_state(problem, 0.0, x);
  if (why.empty()) return std::nullopt;
  std::cerr << fmt::format("eomgen: error: no stability analysis at {}: {}\n", which, why);
  return exit_numerical_failure;
}

std::optional<int> equilibrium_of(const runtime::Problem& problem, const std::vector<std::string>& at_texts,
                                  const std::vector<double>& initial, runtime::Equilibrium& out) {
  const eomgen_model_abi& m = *problem.model;
  if (!at_texts.empty()) {
    auto x = state_from_at(m, initial, at_texts);
    if (!x) return exit_user_error;
    if (auto status = refuse_unfit(problem, *x, "the state given by --at")) return status;
    out = runtime::check_equilibrium(problem, *x);
    if (!out.moving.empty()) {
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: {} moves a coordinate that "
                               "is not cyclic, so the configuration and with it the forces change\n  hint: only cyclic "
                               "coordinates (ones no equation depends on) may move in a steady motion; leave out --at "
                               "to search for an equilibrium\n", out.moving);
      return exit_user_error;
    }
    if (!out.converged) {
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: the largest residual of "
                               "the equations of motion is {:.3g} (tolerance {:.3g})\n  hint: leave out --at to search "
                               "for one from the model's initial values\n", out.residual, out.tolerance);
      return exit_user_error;
    }
    return std::nullopt;
  }
  if (auto status = refuse_unfit(problem, initial, "the model's initial state (where the search starts)")) return status;
  out = runtime::find_equilibrium(problem, initial);
  if (!out.converged) {
    std::cerr << fmt::format("eomgen: no equilibrium found near the model's initial values after {} Newton steps "
                             "(largest residual {:.3g})\n  hint: name one with --at q=VALUE (and --at 'der(q)=VALUE' for a "
                             "steady motion)\n", out.iterations, out.residual);
    return exit_numerical_failure;
  }
  return refuse_unfit(problem, out.state, "the equilibrium found");
}

namespace {

// the whole `eomgen stability` job for one set of options
int stability(const Options& o) {
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
  const eomgen_model_abi& m = *loaded.compiled->abi();
  if (auto status = stability_refusal(loaded, o.model, !o.symbolic.empty())) return *status;
  if (auto status = periodic_stability(loaded, {o.at, o.symbolic, o.period, o.json})) return *status;
  runtime::Equilibrium eq;
  if (auto status = equilibrium_of(loaded.problem, o.at, loaded.initial_state, eq)) return *status;
  std::optional<StabilityConditions> conditions;
  if (!o.symbolic.empty()) {
    std::vector<std::string> kept = split_names(o.symbolic);
    for (const std::string& k : kept)
      if (index_of(m.parameter_names, m.num_parameters, k) < 0) {
        std::cerr << fmt::format("eomgen: error: --symbolic {}: not a parameter; {}\n", k,
                                 suggest(k, std::vector<std::string>(m.parameter_names, m.parameter_names + m.num_parameters), "parameters"));
        return exit_user_error;
      }
    conditions = stability_conditions(loaded.equations, kept, loaded.problem.parameters, loaded.problem.inputs, eq.state);
  }
  runtime::StabilityReport report = runtime::analyse_stability(loaded.problem, eq.state);
  runtime::CriticalCase critical = runtime::check_critical_case(loaded.problem, eq.state, report);
  if (o.json) {
    print_json(m, eq, report, conditions, critical);
  } else {
    print_text(m, eq, report, conditions);
    print_critical_case(critical);
  }
  return exit_success;
}

}  // namespace

Command add_stability_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("stability", "Equilibrium, linearization and stability of a model");
  auto o = std::make_shared<Options>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--at", o->at, "Equilibrium value, one per flag: --at theta=0 --at 'der(phi)=8'; velocities not named are zero");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--period", o->period, "Period T [s] of time-periodic equations (default: found from sin/cos(w*t) in "
                  "the model); their stability is judged by Floquet multipliers over T")->check(CLI::PositiveNumber);
  cmd->add_option("--symbolic", o->symbolic, "Keep these parameters as symbols and print the Hurwitz conditions: --symbolic b,J");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return stability(*o);
  };
}

int stability_of_model(const std::string& model) {
  Options o;
  o.model = model;
  return stability(o);
}

}  // namespace eomgen::cli
