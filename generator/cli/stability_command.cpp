/// @file `eomgen stability`: the equilibrium, its linearization split by force
/// type, eigenvalues, verdict, modes, Hurwitz test, the classical theorems that
/// apply, and with --symbolic the stability conditions in the parameters.
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/equilibrium.hpp"
#include "analyse/stability_conditions.hpp"
#include "analyse/state_check.hpp"
#include "cli/commands.hpp"
#include "cli/loaded_problem.hpp"
#include "cli/routh_reduction.hpp"
#include "cli/stability_report.hpp"

namespace eomgen::cli {

namespace {

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

}  // namespace

std::optional<int> stability_refusal(const LoadedProblem& loaded, const std::string& model, bool symbolic,
                                      bool on_manifold) {
  // stability and sweep analyse a Lagrange I model on its constraint manifold; the symbolic
  // conditions and `linear` need independent coordinates
  if (loaded.equations.has_multipliers && (symbolic || !on_manifold)) {
    std::cerr << fmt::format("eomgen: error: {} is a Lagrange I model: its coordinates are not independent{}\n  hint: "
                             "derive it with method = \"appell\" (independent pseudo-velocities){}\n", model,
                             symbolic ? ", and symbolic conditions need them" : "",
                             symbolic ? ", or leave out --symbolic (the numeric analysis works on the constraint manifold)" : "");
    return exit_user_error;
  }
  if (symbolic && !loaded.equations.intermediates.empty()) {
    std::cerr << fmt::format("eomgen: error: {}: symbolic stability conditions differentiate equations written out in q; "
                             "those of recursive kinematics hold the frames' quantities\n  hint: use kinematics = "
                             "\"expanded\", or leave out --symbolic (the numeric analysis works from the generated code)\n",
                             model);
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
int stability(const Options& given) {
  Options o = given;
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
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
  runtime::CriticalCase critical = runtime::check_critical_case(loaded.problem, eq.state, report);
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

}  // namespace

Command add_stability_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("stability", "Equilibrium, linearization and stability of a model");
  auto o = std::make_shared<Options>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--at", o->at, "Equilibrium value, one per flag: --at theta=0 --at 'der(phi)=8'; velocities not named "
                  "are zero. --at p_phi=VALUE holds the momentum of the cyclic coordinate phi and analyses Routh's "
                  "reduced system");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--period", o->period, "Period T [s] of time-periodic equations (default: found from sin/cos(w*t) in "
                  "the model); their stability is judged by Floquet multipliers over T")->check(positive_number());
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
