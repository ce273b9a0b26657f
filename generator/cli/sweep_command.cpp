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
#include "analyse/stability_conditions.hpp"
#include "analyse/stability_map.hpp"
#include "analyse/time_dependence.hpp"
#include "cli/commands.hpp"
#include "cli/count_progress.hpp"
#include "cli/eigenvalue_sweep_output.hpp"
#include "cli/loaded_problem.hpp"
#include "cli/ranked_run.hpp"
#include "cli/stop_signal.hpp"
#include "common/output_file.hpp"
#include "derive/initial_state.hpp"
#include "distribute/distributed_sweep.hpp"
#include "distribute/ranks.hpp"
#include "report/reports.hpp"
#include "symbolic/evaluate.hpp"

namespace eomgen::cli {

namespace {


struct Options {
  std::string model;
  std::vector<std::string> params, at, sets;
  std::string csv, plot;
  bool symbolic = false, json = false;
  unsigned threads = 0;
};

// "name=LO:HI:N"
std::optional<runtime::SweepAxis> parse_axis(const eomgen_model_abi& m, const std::string& text, std::string& name) {
  std::size_t eq = text.find('='), c1 = text.find(':', eq), c2 = text.find(':', c1 + 1);
  if (eq == std::string::npos || c1 == std::string::npos || c2 == std::string::npos) {
    std::cerr << fmt::format("eomgen: error: --param '{}': expected NAME=LOW:HIGH:COUNT, e.g. --param b=0.1:2:200\n", text);
    return std::nullopt;
  }
  name = text.substr(0, eq);
  int index = index_of(m.parameter_names, m.num_parameters, name);
  if (index < 0) {
    std::cerr << fmt::format("eomgen: error: --param {}: not a parameter; {}\n", name,
                             suggest(name, std::vector<std::string>(m.parameter_names, m.parameter_names + m.num_parameters), "parameters"));
    return std::nullopt;
  }
  try {
    // every character of each field read: std::stoi("2e9") is 2, which ran two points silently
    auto whole = [](const std::string& field, auto read) {
      std::size_t used = 0;
      auto value = read(field, &used);
      if (used != field.size()) throw std::invalid_argument(field);
      return value;
    };
    auto real = [](const std::string& f, std::size_t* used) { return std::stod(f, used); };
    auto integer = [](const std::string& f, std::size_t* used) { return std::stol(f, used); };
    long count = whole(text.substr(c2 + 1), integer);
    if (count < 2 || count > 100000) throw std::invalid_argument("count");
    runtime::SweepAxis axis{index, whole(text.substr(eq + 1, c1 - eq - 1), real), whole(text.substr(c1 + 1, c2 - c1 - 1), real),
                            static_cast<int>(count)};
    if (!(axis.high > axis.low)) throw std::invalid_argument("range");
    return axis;
  } catch (const std::exception&) {
    std::cerr << fmt::format("eomgen: error: --param '{}': need LOW < HIGH (numbers) and a whole COUNT with 2 <= COUNT <= "
                             "100000\n", text);
    return std::nullopt;
  }
}

// > 0 where every symbolic condition holds: the smallest condition, scaled by its size
std::vector<double> symbolic_margin(const LoadedProblem& loaded, const runtime::StabilityMap& map,
                                    const std::string& x_name, const std::string& y_name, const std::vector<double>& state) {
  StabilityConditions c = stability_conditions(loaded.equations, {x_name, y_name}, loaded.problem.parameters,
                                               loaded.problem.inputs, state);
  const Symbols& s = loaded.equations.symbols;
  std::vector<double> margin(map.degree.size(), NAN);
  for (int j = 0; j < map.y.count; ++j)
    for (int i = 0; i < map.x.count; ++i) {
      std::size_t at = static_cast<std::size_t>(j) * map.x.count + i;
      const std::vector<double>& x = map.states[at].empty() ? state : map.states[at];
      auto value_of = [&](const GiNaC::symbol& y) -> double {
        if (y.get_name() == x_name) return map.x.value(i);
        if (y.get_name() == y_name) return map.y.value(j);
        for (std::size_t k = 0; k < s.coordinates.size(); ++k) {
          if (GiNaC::ex(y).is_equal(s.coordinates[k])) return x[k];
          if (GiNaC::ex(y).is_equal(s.velocities[k])) return x[s.coordinates.size() + k];
        }
        throw std::runtime_error("unexpected symbol " + y.get_name());
      };
      // a condition that vanishes identically holds nowhere strictly: at best marginal
      double smallest = c.vanishing.empty() ? INFINITY : 0.0;
      for (const GiNaC::ex& condition : c.conditions) smallest = std::min(smallest, evaluate(condition, value_of));
      margin[at] = smallest;
    }
  return margin;
}

// one parameter: the eigenvalues along it, about the model's initial state at each value
int run_eigenvalue_sweep(const Options& o, const LoadedProblem& loaded, const runtime::Equilibrium& eq) {
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

int run_sweep(const Options& o) {
  const distribute::Ranks& ranks = distribute::Ranks::world();
  QuietUnlessRoot quiet(ranks);
  LoadedProblem loaded;
  if (auto status = load_on_every_rank(ranks, o.model, o.sets, loaded)) return *status;
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

}  // namespace

Command add_sweep_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("sweep", "Eigenvalues along one parameter, or a stability map over two");
  auto o = std::make_shared<Options>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--param", o->params,
                  "Swept parameter, once (eigenvalues along it: --param v=0:10:1001) or twice (a map: --param b=0.05:2:200 "
                  "--param J=0.05:3:200)");
  cmd->add_option("--at", o->at, "A fixed equilibrium, one value per flag (default: re-found at every point)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_flag("--symbolic", o->symbolic, "Draw the boundary of the symbolic Hurwitz conditions over the map");
  cmd->add_option("--threads", o->threads, "Threads (default: all cores)");
  cmd->add_option("-o,--output", o->csv, "CSV: the eigenvalues at each value, or the map (x, y, stability degree)");
  cmd->add_option("--plot", o->plot, "Chart as PNG: the eigenvalues against the parameter, or the map");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return run_sweep(*o);
  };
}

}  // namespace eomgen::cli
