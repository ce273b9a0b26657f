/// @file `eomgen stability` of a model whose equations depend on time: refused when
/// the dependence is not periodic, else the Floquet analysis of the equilibrium over
/// the period found from the model (or given with --period).
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "analyse/floquet.hpp"
#include "symbolic_analysis/time_dependence.hpp"
#include "studies/equilibrium_choice.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/periodic_stability.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"

namespace eomgen::studies {

namespace {


std::string multiplier_text(std::complex<double> z) {
  if (std::abs(z.imag()) <= 1e-12 * std::max(1.0, std::abs(z))) return fmt::format("{:.9g}", z.real() + 0.0);
  return fmt::format("{:.9g} {} {:.9g}i", z.real() + 0.0, z.imag() < 0 ? "-" : "+", std::abs(z.imag()));
}

void print_text(const eomgen_model_abi& m, const std::vector<double>& x, const TimeDependence& time,
                const runtime::FloquetReport& r) {
  std::string where;
  for (std::size_t i = 0; i < m.num_states; ++i)
    if (i < m.num_coordinates ? !m.is_cyclic[i] : x[i] != 0)
      where += fmt::format("{}{} = {:.9g}", where.empty() ? "" : ", ", m.state_names[i], x[i]);
  std::cout << fmt::format("{}: equilibrium {} of the periodic system (x' = 0 at every t)\n", m.name, where.empty() ? "at rest" : where);
  std::cout << fmt::format("  time-periodic equations{}: Floquet analysis over the period T = {:.12g} s\n",
                           time.frequencies.empty() ? "" : " (" + time.frequencies + ")", r.period);
  std::string state;
  for (const std::string& s : r.state_names) state += (state.empty() ? "" : ", ") + s;
  std::cout << "  reduced state: " << state << "\n";
  std::cout << fmt::format("  monodromy matrix Phi(T) ({} RK4 steps per period, estimated error {:.1e}):\n",
                           r.steps_per_period, r.error_estimate);
  for (Eigen::Index i = 0; i < r.monodromy.rows(); ++i) {
    std::cout << "   ";
    for (Eigen::Index j = 0; j < r.monodromy.cols(); ++j) std::cout << fmt::format(" {:>14.9g}", r.monodromy(i, j) + 0.0);
    std::cout << "\n";
  }
  std::cout << "  Floquet multipliers (modulus):\n";
  for (auto mu : r.multipliers) std::cout << fmt::format("    {:<36} |mu| = {:.12g}\n", multiplier_text(mu), std::abs(mu));
  if (r.cyclic_unit_multipliers)
    std::cout << fmt::format("  {} multiplier(s) 1 of conserved cyclic momenta left out of the verdict\n", r.cyclic_unit_multipliers);
  std::cout << fmt::format("  verdict: {} ({})\n", r.verdict, r.reason);
}

void print_json(const eomgen_model_abi& m, const std::vector<double>& x, const TimeDependence& time,
                const runtime::FloquetReport& r) {
  std::string equilibrium, multipliers, moduli, rows, names;
  for (std::size_t i = 0; i < m.num_states; ++i)
    equilibrium += fmt::format("{}{}: {}", i ? ", " : "", json_quoted(m.state_names[i]), json_number(x[i]));
  for (auto mu : r.multipliers) {
    multipliers += fmt::format("{}[{}, {}]", multipliers.empty() ? "" : ", ", json_number(mu.real()), json_number(mu.imag()));
    moduli += (moduli.empty() ? "" : ", ") + json_number(std::abs(mu));
  }
  for (Eigen::Index i = 0; i < r.monodromy.rows(); ++i) {
    std::string row;
    for (Eigen::Index j = 0; j < r.monodromy.cols(); ++j) row += (j ? ", " : "") + json_number(r.monodromy(i, j));
    rows += (i ? ", [" : "[") + row + "]";
  }
  for (const std::string& s : r.state_names) names += (names.empty() ? "" : ", ") + json_quoted(s);
  std::cout << fmt::format(
      "{{\"model\": \"{}\", \"analysis\": \"floquet\", \"period\": {}, \"frequencies\": {}, \"equilibrium\": {{{}}}, "
      "\"state\": [{}], \"monodromy\": [{}], \"multipliers\": [{}], \"moduli\": [{}], \"error_estimate\": {}, "
      "\"steps_per_period\": {}, \"cyclic_unit_multipliers\": {}, \"verdict\": \"{}\", \"reason\": {}}}\n",
      m.name, json_number(r.period), json_quoted(time.frequencies), equilibrium, names, rows, multipliers, moduli,
      json_number(r.error_estimate), r.steps_per_period, r.cyclic_unit_multipliers, r.verdict, json_quoted(r.reason));
}

}  // namespace

std::optional<int> periodic_stability(const LoadedProblem& loaded, const PeriodicOptions& o) {
  const eomgen_model_abi& m = *loaded.compiled->abi();
  TimeDependence time = time_dependence(loaded.equations, loaded.problem.parameters);
  if (!time.depends_on_time) {
    if (o.period > 0) {
      std::cerr << "eomgen: error: --period: the equations of this model do not depend on time; leave it out\n";
      return exit_user_error;
    }
    return std::nullopt;
  }
  if (o.period <= 0 && !time.period) {
    std::cerr << fmt::format("eomgen: error: the equations depend explicitly on time, and not periodically ({}): an "
                             "equilibrium at frozen t says nothing about such a system, and Floquet theory needs a "
                             "period\n  hint: give --period P if the equations are periodic with period P all the same\n",
                             time.not_periodic);
    return exit_user_error;
  }
  if (!o.symbolic.empty()) {
    std::cerr << "eomgen: error: --symbolic: the equations depend on time; symbolic Hurwitz conditions need an "
                 "autonomous system (leave out --symbolic for the Floquet analysis)\n";
    return exit_user_error;
  }
  double period = o.period > 0 ? o.period : *time.period;
  if (o.period > 0) time.frequencies = time.period ? time.frequencies + ", --period given" : "--period given";
  runtime::Equilibrium eq;
  if (auto status = equilibrium_of(loaded.problem, o.at, loaded.initial_state, eq)) return status;
  double residual = runtime::periodic_equilibrium_residual(loaded.problem, eq.state, period);
  if (!(residual <= eq.tolerance)) {
    std::cerr << fmt::format("eomgen: error: the state {} is at rest at t = 0 but not over the whole period: the largest "
                             "|x'| over one period is {:.3g}; Floquet analysis here needs an equilibrium of the periodic "
                             "system (x' = 0 at every t), such as the inverted pendulum on a driven support\n  hint: "
                             "name one with --at\n", m.name, residual);
    return exit_user_error;
  }
  if (double defect = runtime::periodicity_defect(loaded.problem, eq.state, period); !(defect <= 1e-9)) {
    std::cerr << fmt::format("eomgen: error: --period {:g}: the linearized equations are not periodic with this period "
                             "(A(t + T) and A(t) differ by {:.3g} relative)\n  hint: {}\n", period, defect,
                             time.period ? fmt::format("the model's own period is {:.9g} s", *time.period)
                                         : "the model's time dependence is not periodic: " + time.not_periodic);
    return exit_user_error;
  }
  std::cerr << fmt::format("eomgen: Floquet analysis of {} over T = {:.9g} s\n", m.name, period);
  runtime::FloquetReport r = runtime::floquet_analysis(loaded.problem, eq.state, period);
  if (o.json) print_json(m, eq.state, time, r);
  else print_text(m, eq.state, time, r);
  return exit_success;
}

}  // namespace eomgen::studies
