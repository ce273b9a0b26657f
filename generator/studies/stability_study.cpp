/// @file `eomgen stability`: the equilibrium, its linearization split by force
/// type, eigenvalues, verdict, modes, Hurwitz test, the classical theorems that
/// apply, and with --symbolic the stability conditions in the parameters.
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/critical_case.hpp"
#include "analyse/linear_stability.hpp"
#include "common/count_progress.hpp"
#include "studies/equilibrium_choice.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/periodic_stability.hpp"
#include "studies/routh_reduction.hpp"
#include "studies/stability_report.hpp"
#include "studies/stability_study.hpp"
#include "symbolic_analysis/stability_conditions.hpp"

namespace eomgen::studies {

namespace {

std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream s(list);
  for (std::string name; std::getline(s, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

}  // namespace

// the whole `eomgen stability` job for one set of options
int stability(const StabilityOptions& given) {
  StabilityOptions o = given;
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded, {}, model_written_out(!o.symbolic.empty()))) return *status;
  RouthRequest routh = routh_request(*loaded.compiled->abi(), o.at);
  if (!routh.eliminated.empty()) {
    o.at = routh.at;
    if (auto status = load_reduced_problem(o.model, o.sets, routh, loaded)) return *status;
  }
  const eomgen_model_abi& m = *loaded.compiled->abi();
  if (auto status = stability_refusal(loaded, o.model, !o.symbolic.empty(), true)) return *status;
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
    for (const std::string& k : conditions->absent) {
      std::cerr << fmt::format("eomgen: error: --symbolic {0}: {0} appears neither in the characteristic polynomial nor in "
                               "the equilibrium's equations, so no condition can be stated in it\n  hint: a parameter "
                               "that sets only the initial state (a spin rate, say) was taken at its value {1}: give "
                               "that state with --at, or keep a parameter of the equations\n",
                               k, loaded.problem.parameters[static_cast<std::size_t>(index_of(m.parameter_names, m.num_parameters, k))]);
      return exit_user_error;
    }
  }
  runtime::StabilityReport report = runtime::analyse_stability(loaded.problem, eq.state);
  runtime::CriticalCase critical = runtime::check_critical_case(
      loaded.problem, eq.state, report, count_progress("stability", "perturbed runs of the critical case"));
  bool reduced = !routh.eliminated.empty();
  if (o.json) {
    print_stability_json(m, eq, report, conditions, critical, reduced ? routh_json(loaded.equations, routh) : "");
  } else {
    if (reduced) std::cout << routh_text(loaded.equations, routh);
    print_stability_text(m, eq, report, conditions);
    print_critical_case(critical);
  }
  return exit_success;
}

int stability_of_model(const std::string& model) {
  StabilityOptions o;
  o.model = model;
  return stability(o);
}

}  // namespace eomgen::studies
