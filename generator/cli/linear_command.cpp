/// @file `eomgen linear`: the linearized system about an equilibrium or steady motion
/// (found as `stability` finds it), solved: eigenvalues with multiplicities and Jordan
/// blocks, natural frequencies and mass-normalized modes, and Φ(t) = e^{At} (Hiller §6, §8.1).
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/linear_report.hpp"
#include "cli/loaded_model.hpp"

namespace eomgen::cli {

namespace {

struct Options {
  std::string model, times;
  std::vector<std::string> at, sets;
  bool json = false;
};

std::optional<std::vector<double>> parse_times(const std::string& list) {
  std::vector<double> times;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');) {
    char* end = nullptr;
    double t = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(t)) {
      std::cerr << fmt::format("eomgen: error: --times {}: '{}' is not a number; expected e.g. --times 0.5,1,10\n", list, item);
      return std::nullopt;
    }
    times.push_back(t);
  }
  return times;
}

int linear(const Options& o) {
  auto times = parse_times(o.times);
  if (!times) return exit_user_error;
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
  if (auto status = stability_refusal(loaded, o.model, false)) return *status;
  runtime::Equilibrium eq;
  if (auto status = equilibrium_of(loaded.problem, o.at, loaded.initial_state, eq)) return *status;
  LinearReport report = linear_report(loaded.problem, eq.state, *times);
  const eomgen_model_abi& m = *loaded.compiled->abi();
  o.json ? print_linear_json(m, eq, report) : print_linear_text(m, eq, report);
  return exit_success;
}

}  // namespace

Command add_linear_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("linear", "The linearized system about an equilibrium, solved: eigenvalues with "
                                               "Jordan structure, natural modes, fundamental matrix");
  auto o = std::make_shared<Options>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--at", o->at, "Equilibrium value, one per flag, as for `stability` (default: searched from the "
                  "model's initial values)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--times", o->times, "Times at which to print the fundamental matrix Phi(t) = e^(At): --times 0.5,1,10");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return linear(*o);
  };
}

}  // namespace eomgen::cli
