/// @file `eomgen sweep`: the eigenvalues along one parameter with the crossings of the
/// imaginary axis, or a stability map over two parameters, on all cores, with the
/// symbolic boundary over it when asked.
#include <atomic>
#include <cmath>
#include <csignal>
#include <iostream>

#include <fmt/format.h>

#include "analyse/eigenvalue_sweep.hpp"
#include "analyse/equilibrium.hpp"
#include "analyse/stability_map.hpp"
#include "common/count_progress.hpp"
#include "common/output_file.hpp"
#include "common/stop_signal.hpp"
#include "derive/initial_state.hpp"
#include "distribute/distributed_sweep.hpp"
#include "distribute/ranks.hpp"
#include "report/reports.hpp"
#include "studies/eigenvalue_sweep_output.hpp"
#include "studies/equilibrium_choice.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/ranked_run.hpp"
#include "studies/sweep_axes.hpp"
#include "studies/sweep_study.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic_analysis/stability_conditions.hpp"
#include "symbolic_analysis/time_dependence.hpp"

namespace eomgen::studies {

namespace {

// one parameter: the eigenvalues along it, about the model's initial state at each value
int run_eigenvalue_sweep(const SweepOptions& o, const LoadedProblem& loaded, const runtime::Equilibrium& eq) {
  const eomgen_model_abi& m = *loaded.compiled->abi();
  std::string name;
  auto axis = parse_axis(m, o.params[0], name);
  if (!axis) return exit_user_error;
  runtime::StartState start = [&](const std::vector<double>& parameters) -> std::optional<std::vector<double>> {
    if (!o.at.empty()) return eq.state;
    std::string failed;
    return initial_state(loaded.equations, parameters, failed);
  };
  runtime::EigenvalueSweep s;
  const distribute::Ranks& ranks = distribute::Ranks::world();
  {
    StopOnSignal stop;
    s = distribute::distributed_eigenvalue_sweep(ranks, loaded.problem, start, !o.at.empty(), *axis, 1e-10, o.threads,
                                                 count_progress("sweep", ranks.size() > 1 ? "points, rank 0's share" : "points"), StopOnSignal::flag());
  }
  if (!ranks.is_root()) return s.interrupted ? exit_numerical_failure : exit_success;
  if (s.interrupted) std::cerr << "\neomgen sweep: interrupted; no crossings are reported\n";
  if (!o.csv.empty())
    if (std::string failure = write_file_atomically(o.csv, eigenvalue_sweep_csv(s, name)); !failure.empty()) {
      std::cerr << "eomgen: " << failure << "\n";
      return exit_user_error;
    }
  if (!o.plot.empty()) {
    std::string title = fmt::format("{}: eigenvalues against {} (dashed: crossings of the imaginary axis)", m.name, name);
    if (std::string failure = runtime::draw_eigenvalue_sweep(s, name, title, o.plot); !failure.empty())
      std::cerr << "eomgen: warning: no chart: " << failure << "\n";
  }
  if (o.json) print_eigenvalue_sweep_json(s, m.name, name, ranks);
  else print_eigenvalue_sweep_text(s, m.name, name, ranks);
  return s.interrupted ? exit_numerical_failure : exit_success;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  const distribute::Ranks& ranks = distribute::Ranks::world();
  QuietUnlessRoot quiet(ranks);
  LoadedProblem loaded;
  if (auto status = load_on_every_rank(ranks, o.model, o.sets, loaded, model_written_out(o.symbolic))) return *status;
  if (auto status = stability_refusal(loaded, o.model, o.symbolic, true)) return *status;
  if (time_dependence(loaded.equations, loaded.problem.parameters).depends_on_time) {
    std::cerr << "eomgen: error: the equations depend on time: a map of eigenvalues at frozen t would be wrong for them\n"
                 "  hint: judge single points with `eomgen stability MODEL --set ...` (Floquet multipliers for periodic "
                 "equations)\n";
    return exit_user_error;
  }
  const eomgen_model_abi& m = *loaded.compiled->abi();
  if (o.params.size() != 1 && o.params.size() != 2) {
    std::cerr << "eomgen: error: give one --param NAME=LOW:HIGH:COUNT (eigenvalues along it) or two (a stability map)\n";
    return exit_user_error;
  }
  runtime::Equilibrium eq;
  if (auto status = equilibrium_of(loaded.problem, o.at, loaded.initial_state, eq)) return *status;
  if (o.params.size() == 1) {
    if (o.symbolic) {
      std::cerr << "eomgen: error: --symbolic draws the Hurwitz boundary over a map of two parameters\n";
      return exit_user_error;
    }
    return run_eigenvalue_sweep(o, loaded, eq);
  }
  std::string x_name, y_name;
  auto x = parse_axis(m, o.params[0], x_name), y = parse_axis(m, o.params[1], y_name);
  if (!x || !y) return exit_user_error;
  runtime::StabilityMap map;
  {
    StopOnSignal stop;
    map = distribute::distributed_map(ranks, loaded.problem, eq.state, !o.at.empty(), *x, *y, o.threads, count_progress("sweep", ranks.size() > 1 ? "points, rank 0's share" : "points"),
                                      StopOnSignal::flag());
  }
  if (!ranks.is_root()) return map.interrupted ? exit_numerical_failure : exit_success;
  if (map.interrupted) std::cerr << "\neomgen sweep: interrupted; keeping the points computed so far\n";
  std::vector<double> margin;
  if (o.symbolic) margin = symbolic_margin(loaded, map, x_name, y_name, eq.state);
  if (!o.csv.empty()) {
    std::string text = fmt::format("{},{},stability_degree{}\n", x_name, y_name, o.symbolic ? ",symbolic_margin" : "");
    for (int j = 0; j < map.y.count; ++j)
      for (int i = 0; i < map.x.count; ++i) {
        std::size_t at = static_cast<std::size_t>(j) * map.x.count + i;
        text += fmt::format("{:.17g},{:.17g},{:.17g}", map.x.value(i), map.y.value(j), map.degree[at]);
        text += o.symbolic ? fmt::format(",{:.17g}\n", margin[at]) : "\n";
      }
    if (std::string failure = write_file_atomically(o.csv, text); !failure.empty()) {
      std::cerr << "eomgen: " << failure << "\n";
      return exit_user_error;
    }
  }
  if (!o.plot.empty()) {
    std::string title = fmt::format("{}: stability map (blue stable, red unstable)", m.name);
    if (std::string failure = runtime::draw_stability_map(map, x_name, y_name, title, margin, o.plot); !failure.empty())
      std::cerr << "eomgen: warning: no chart: " << failure << "\n";
  }
  long stable = 0;
  for (double d : map.degree) stable += d < 0;
  long total = static_cast<long>(map.x.count) * map.y.count;
  double rate = map.computed / std::max(map.seconds, 1e-9);
  if (o.json)
    std::cout << fmt::format("{{\"model\": \"{}\", \"x\": \"{}\", \"y\": \"{}\", \"points\": {}, \"computed\": {}, "
                             "\"asymptotically_stable\": {}, \"seconds\": {:.6g}, \"points_per_second\": {:.6g}, "
                             "\"interrupted\": {}, \"ranks\": {}}}\n",
                             m.name, x_name, y_name, total, map.computed, stable, map.seconds, rate,
                             map.interrupted ? "true" : "false", ranks.size());
  else
    std::cout << fmt::format("{}: {} x {} map of the stability degree over {} and {}: {} of {} points computed in "
                             "{:.3f} s ({:.0f} points/s) on {}, {} asymptotically stable\n",
                             m.name, map.x.count, map.y.count, x_name, y_name, map.computed, total, map.seconds, rate,
                             ranks.description(), stable);
  return map.interrupted ? exit_numerical_failure : exit_success;
}

}  // namespace eomgen::studies
