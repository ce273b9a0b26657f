/// @file `eomgen linear`: the linearized system about an equilibrium or steady motion
/// (found as `stability` finds it), solved: eigenvalues with multiplicities and Jordan
/// blocks, natural frequencies and mass-normalized modes, and Φ(t) = e^{At} (Hiller §6, §8.1).
#include <algorithm>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/time_dependence.hpp"
#include "cli/commands.hpp"
#include "cli/linear_charts.hpp"
#include "cli/linear_report.hpp"
#include "cli/linear_response_output.hpp"
#include "cli/loaded_problem.hpp"

namespace eomgen::cli {

namespace {

struct Options {
  std::string model, times, outputs;
  std::vector<std::string> at, sets, transfer, bode;
  bool json = false, symbolic = false;
  ResponseOptions response;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// --transfer u:y pairs
std::optional<std::vector<std::pair<std::string, std::string>>> parse_pairs(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& t : texts) {
    std::size_t colon = t.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == t.size()) {
      std::cerr << fmt::format("eomgen: error: --transfer {}: expected INPUT:OUTPUT, e.g. --transfer F:x\n", t);
      return std::nullopt;
    }
    pairs.push_back({t.substr(0, colon), t.substr(colon + 1)});
  }
  return pairs;
}

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
  auto pairs = parse_pairs(o.transfer), bode = parse_pairs(o.bode);
  if (!times || !pairs || !bode) return exit_user_error;
  for (const auto& pair : *bode)
    if (std::find(pairs->begin(), pairs->end(), pair) == pairs->end()) pairs->push_back(pair);
  if (!bode->empty() && o.response.plot.empty()) {
    std::cerr << "eomgen: error: --bode needs --plot FILE.png (the chart is FILE_bode_INPUT_OUTPUT.png)\n";
    return exit_user_error;
  }
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
  if (auto status = stability_refusal(loaded, o.model, false, false)) return *status;
  // the linear analyses need A, B constant: a linearization frozen at t = 0 of equations that
  // depend on time (a periodically forced Duffing oscillator) would be answered without a word
  if (TimeDependence time = time_dependence(loaded.equations, loaded.problem.parameters); time.depends_on_time) {
    std::cerr << fmt::format("eomgen: error: the equations depend explicitly on time ({}): their linearization is not a "
                             "constant A, and one frozen at t = 0 says nothing about the motion\n  hint: `eomgen "
                             "stability` judges periodic equations by their Floquet multipliers\n",
                             time.period ? time.frequencies : time.not_periodic);
    return exit_user_error;
  }
  runtime::Equilibrium eq;
  if (auto status = equilibrium_of(loaded.problem, o.at, loaded.initial_state, eq)) return *status;
  const eomgen_model_abi& m = *loaded.compiled->abi();
  LinearRequest request{*times, split(o.outputs), *pairs, o.symbolic};
  if (std::string unknown = unknown_names(m, request); !unknown.empty()) {
    std::cerr << fmt::format("eomgen: error: {}: not an input, a state or an output of {}\n", unknown, m.name);
    return exit_user_error;
  }
  // the exact (symbolic) parts need equations written out in q, which recursive kinematics does not give
  const Equations* symbolic = loaded.equations.intermediates.empty() ? &loaded.equations : nullptr;
  LinearReport report = linear_report(loaded.problem, eq.state, request, symbolic);
  // with --response the CSV goes to standard output unless -o names a file, so the report is left out then
  if (wants_response(o.response)) return *write_linear_response(m, report, o.response);
  o.json ? print_linear_json(m, eq, report) : print_linear_text(m, eq, report);
  if (!o.response.plot.empty()) draw_linear_charts(m, report, o.response.plot, *bode);
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
  cmd->add_option("--outputs", o->outputs, "Outputs y = C x + D u for observability: states or [outputs] by name, "
                  "comma-separated (default: the model's [outputs])");
  cmd->add_option("--transfer", o->transfer, "Transfer function from an input to an output (a state or an [outputs] "
                  "entry), one pair per flag: --transfer F:x");
  cmd->add_option("--times", o->times, "Times at which to print the fundamental matrix Phi(t) = e^(At): --times 0.5,1,10");
  cmd->add_flag("--symbolic", o->symbolic, "Phi(t) and the --transfer functions G(s) in closed form, in the parameters "
                "where the characteristic polynomial factors into linear and quadratic factors over them, else at their "
                "values (Lagrange II models with exact A)");
  cmd->add_option("--response", o->response.response, "Response of the linearized system, written as CSV of the "
                  "deviations from the equilibrium: initial (with --initial), impulse:INPUT, step:INPUT (unit), "
                  "harmonic:INPUT:OMEGA (sin(OMEGA t))");
  cmd->add_option("--input", o->response.input, "Response to one input as a function of time: --input 'F=step(2)' (a unit "
                  "step at t = 2), 'F=0.5*impulse(0)', 'F=sin(3*t)', 'F=2*cos(3*t)'");
  cmd->add_option("--initial", o->response.initials, "Initial deviation, one per flag: --initial x1=0.01");
  cmd->add_option("--t-end", o->response.t_end, "End time of the response [s] (default 10)");
  cmd->add_option("--dt-out", o->response.dt_out, "Output interval of the response [s] (default 0.01)");
  cmd->add_option("-o,--output", o->response.csv, "CSV file for the response (default: standard output)");
  cmd->add_option("--plot", o->response.plot, "Charts (PNG): with --response the response's coordinates; otherwise "
                  "FILE_modes.png (the mode shapes) and FILE_bode_U_Y.png for each --bode pair");
  cmd->add_option("--bode", o->bode, "Bode chart of a transfer function, one pair per flag: --bode F:x (with --plot)");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return linear(*o);
  };
}

}  // namespace eomgen::cli
