/// @file `eomgen linear`: the linearized system about an equilibrium or steady motion
/// (found as `stability` finds it), solved: eigenvalues with multiplicities and Jordan
/// blocks, natural frequencies and mass-normalized modes, and Φ(t) = e^{At} (Hiller §6, §8.1).
#include <algorithm>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "studies/equilibrium_choice.hpp"
#include "studies/exit_status.hpp"
#include "studies/linear_charts.hpp"
#include "studies/linear_report.hpp"
#include "studies/linear_response_output.hpp"
#include "studies/linear_study.hpp"
#include "studies/loaded_problem.hpp"
#include "symbolic_analysis/time_dependence.hpp"

namespace eomgen::studies {

namespace {

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

}  // namespace

int linear(const LinearOptions& o) {
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
  if (auto status = load_problem(o.model, o.sets, loaded, {}, model_written_out(o.symbolic))) return *status;
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

}  // namespace eomgen::studies
