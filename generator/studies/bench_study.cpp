/// @file `eomgen bench`: every integrator at a range of tolerances against a reference
/// solution; writes the work-precision charts, the runs and a report with the verdict.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/work_precision.hpp"
#include "common/output_file.hpp"
#include "common/stop_signal.hpp"
#include "report/work_precision_report.hpp"
#include "studies/bench_study.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

namespace {

// "1e-3:1e-12:10": from the first to the second, dividing by the third
std::optional<std::vector<double>> tolerance_range(const std::string& text) {
  std::vector<double> parts;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, ':');) {
    try {
      parts.push_back(std::stod(part));
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (parts.size() != 3 || !(parts[0] > 0) || !(parts[1] > 0) || !(parts[0] >= parts[1]) || !(parts[2] > 1))
    return std::nullopt;
  std::vector<double> out;
  for (double t = parts[0]; t >= parts[1] * (1 - 1e-9); t /= parts[2]) out.push_back(t);
  return out;
}

std::optional<std::vector<std::string>> chosen_integrators(const std::string& list, const eomgen_model_abi& m) {
  std::vector<std::string> applicable = applicable_integrators(m);
  if (list == "all") return applicable;
  std::vector<std::string> chosen;
  std::stringstream s(list);
  for (std::string name; std::getline(s, name, ',');) {
    if (std::find(applicable.begin(), applicable.end(), name) == applicable.end()) {
      std::cerr << fmt::format("eomgen: error: --integrators: '{}' is not an integrator for this model; {}\n", name,
                               suggest(name, applicable, "integrators"));
      return std::nullopt;
    }
    chosen.push_back(name);
  }
  return chosen;
}

}  // namespace

std::vector<std::string> applicable_integrators(const eomgen_model_abi& m) {
  std::vector<std::string> names;
  for (const std::string& name : runtime::integrator_names()) {
    if (name != "reference" && runtime::integrator_refusal(m, name).empty()) names.push_back(name);
  }
  return names;
}

int bench(const BenchOptions& o) {
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
  const eomgen_model_abi& m = *loaded.compiled->abi();
  auto tolerances = tolerance_range(o.tolerances);
  if (!tolerances) {
    std::cerr << "eomgen: error: --tolerances takes FROM:TO:FACTOR, e.g. 1e-3:1e-12:10 (FROM >= TO > 0, FACTOR > 1)\n";
    return exit_user_error;
  }
  auto integrators = chosen_integrators(o.integrators, m);
  if (!integrators) return exit_user_error;
  if (!(o.t_end > 0) || o.dt_out < 0 || o.step_count < 2) {
    std::cerr << "eomgen: error: need --t-end > 0, --dt-out >= 0 and --step-count >= 2\n";
    return exit_user_error;
  }
  runtime::WorkPrecisionSettings s;
  s.t_end = o.t_end;
  s.dt_out = o.dt_out > 0 ? o.dt_out : o.t_end / 200;
  s.integrators = *integrators;
  s.tolerances = *tolerances;
  // fixed steps from a quarter of the output interval (larger ones are cut at every output time)
  for (int k = 0; k < o.step_count; ++k) s.steps.push_back(s.dt_out / 4 / std::pow(2.0, k));
  s.energy_histories = m.conserves_energy_without_inputs &&
                       std::all_of(loaded.problem.inputs.begin(), loaded.problem.inputs.end(), [](double u) { return u == 0; });
  s.energy_horizon = o.energy_horizon > 0 ? o.energy_horizon : 100 * o.t_end;
  s.energy_tolerance = o.energy_tolerance;
  s.energy_step = o.energy_step > 0 ? o.energy_step : s.dt_out / 5;
  std::string directory = o.directory.empty() ? "bench-" + std::string(m.name) : o.directory;
  if (std::string failure = make_output_directory(directory); !failure.empty()) {
    std::cerr << "eomgen: error: " << failure << "\n";
    return exit_user_error;
  }
  std::vector<double> x0 = loaded.initial_state;
  if (!assign_states(m, o.initials, "--initial", x0)) return exit_user_error;
  if (!o.horizon_integrator.empty()) {
    bool fixed_step = runtime::is_fixed_step_integrator(o.horizon_integrator);
    if (std::find(integrators->begin(), integrators->end(), o.horizon_integrator) == integrators->end() || fixed_step) {
      std::cerr << "eomgen: error: --horizon needs one of the adaptive integrators of the run\n";
      return exit_user_error;
    }
    s.horizon_integrator = o.horizon_integrator;
  }
  std::cerr << fmt::format("eomgen: bench {}: {} integrators, reference first\n", m.name, integrators->size());
  runtime::WorkPrecision result;
  try {
    StopOnSignal stop;
    s.stop = &StopOnSignal::flag();
    result = runtime::work_precision(loaded.problem, x0, s,
                                     [](const std::string& line) { std::cerr << "eomgen: bench: " << line << "\n"; });
  } catch (const std::runtime_error& why) {
    std::cerr << "eomgen: " << why.what() << "\n";
    return exit_numerical_failure;
  }
  if (result.interrupted && result.runs.empty()) {
    std::cerr << "eomgen: bench interrupted (SIGINT or SIGTERM) during the reference run: nothing written\n";
    return exit_numerical_failure;
  }
  std::string report = runtime::work_precision_markdown(m.name, result, s, loaded.compiled->reference_scalar);
  std::string partial = fmt::format("the bench was interrupted (SIGINT or SIGTERM) after {} runs: a partial bench, whose "
                                    "verdict covers those runs only", result.runs.size());
  if (result.interrupted) report.insert(report.find('\n') + 1, "\n**Partial:** " + partial + ".\n");
  std::vector<std::pair<std::string, std::string>> files{{"report.md", report},
                                                         {"runs.csv", runtime::work_precision_csv(result)}};
  if (!result.energy.empty()) files.push_back({"energy.csv", runtime::energy_csv(result)});
  if (!result.horizons.empty()) files.push_back({"horizons.csv", runtime::horizons_csv(result)});
  for (const auto& [name, text] : files)
    if (std::string failure = write_file_atomically(directory + "/" + name, text); !failure.empty()) {
      std::cerr << "eomgen: error: " << failure << "\n";
      return exit_user_error;
    }
  if (std::string failure = runtime::draw_work_precision(m.name, result, directory); !failure.empty())
    std::cerr << "eomgen: warning: no charts: " << failure << "\n";
  std::string verdict = report.substr(report.find("## Verdict"));
  verdict = verdict.substr(0, verdict.find("\n## Runs"));
  std::cout << verdict << fmt::format("\nReport, runs and charts in {}/\n", directory);
  if (result.interrupted) std::cerr << "eomgen: " << partial << "; kept in " << directory << "/\n";
  return result.interrupted ? exit_numerical_failure : exit_success;
}

int bench_model(const std::string& model, const std::string& directory) {
  BenchOptions o;
  o.model = model;
  o.directory = directory;
  return bench(o);
}

}  // namespace eomgen::studies
