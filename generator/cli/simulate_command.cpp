#include <cmath>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "analyse/integrator_choice.hpp"
#include "analyse/work_precision.hpp"
#include "cli/commands.hpp"
#include "cli/loaded_model.hpp"
#include "common/output_file.hpp"
#include "compile/compile_cache.hpp"
#include "emit/cpp_header.hpp"
#include "emit/formats.hpp"
#include "pipeline.hpp"
#include "report/reports.hpp"
#include "simulation.hpp"

namespace eomgen::cli {

namespace {

double relative_energy_drift(const runtime::Trajectory& t) {
  double e0 = t.energies.front(), worst = 0;
  for (double e : t.energies) worst = std::max(worst, std::abs(e - e0));
  return worst / std::max(std::abs(e0), 1e-300);
}

// the largest |λ| of each multiplier over the run
std::vector<double> largest_multipliers(const eomgen_model_abi& m, const runtime::Trajectory& t) {
  std::vector<double> largest(m.num_multipliers, 0.0);
  for (const auto& row : t.multipliers)
    for (std::size_t i = 0; i < row.size(); ++i) largest[i] = std::max(largest[i], std::abs(row[i]));
  return largest;
}

std::string constraint_summary(const eomgen_model_abi& m, const runtime::SimulationResult& r, bool json) {
  std::vector<double> largest = largest_multipliers(m, r.trajectory);
  if (json) {
    std::string multipliers;
    for (std::size_t i = 0; i < largest.size(); ++i)
      multipliers += fmt::format("{}\"{}\": {:.6g}", i ? ", " : "", m.multiplier_names[i], largest[i]);
    return fmt::format(", \"constraints\": {{\"count\": {}, \"max_position_residual\": {:.6g}, "
                       "\"max_velocity_residual\": {:.6g}, \"projections\": {}, \"max_abs_multipliers\": {{{}}}}}",
                       m.num_constraints, r.max_position_residual, r.max_velocity_residual, r.projections, multipliers);
  }
  std::string out = fmt::format("  constraints: largest |g| = {:.3e}, largest |C q' + b| = {:.3e} over the output times{}\n",
                                r.max_position_residual, r.max_velocity_residual,
                                r.projections ? fmt::format(" ({} projections)", r.projections) : "");
  for (std::size_t i = 0; i < largest.size(); ++i)
    out += fmt::format("  constraint force: max |{}| = {:.6g}\n", m.multiplier_names[i], largest[i]);
  return out;
}

void print_summary(const runtime::SimulationSettings& settings, const eomgen_model_abi& m, const runtime::SimulationResult& r,
                   bool conservative, bool json, const std::string& reference_scalar) {
  const runtime::SolverStatistics& s = r.statistics;
  double drift = relative_energy_drift(r.trajectory);
  if (json) {
    std::string failure = r.failed ? fmt::format("{{\"time\": {:.17g}, \"flag\": {}, \"reason\": \"{}\"}}", r.failure_time,
                                                 r.solver_flag, json_escape(r.failure))
                                   : "null";
    std::cout << fmt::format(
        "{{\"model\": \"{}\", \"integrator\": \"{}\", \"t_start\": {:.17g}, \"t_end\": {:.17g}, \"rows\": {}, "
        "\"statistics\": {{\"steps\": {}, \"rhs_evaluations\": {}, \"jacobian_evaluations\": {}, "
        "\"error_test_failures\": {}, \"convergence_failures\": {}, \"wall_seconds\": {:.6g}}}, "
        "\"conserves_energy\": {}, \"relative_energy_drift\": {:.6g}{}{}, \"failure\": {}}}\n",
        m.name, settings.integrator, settings.t_start, r.trajectory.times.back(), r.trajectory.times.size(), s.steps,
        s.rhs_evaluations, s.jacobian_evaluations, s.error_test_failures, s.convergence_failures, s.wall_seconds,
        conservative ? "true" : "false", drift, m.num_constraints ? constraint_summary(m, r, true) : "",
        std::isnan(r.error_estimate) ? std::string()
                                     : fmt::format(", \"reference_error_estimate\": {:.6g}, \"reference_step\": {:.6g}",
                                                   r.error_estimate, r.reference_step),
        failure);
    return;
  }
  std::cout << fmt::format("{}: {} from t = {:g} to {:.9g}, {} output rows\n", m.name, settings.integrator,
                           settings.t_start, r.trajectory.times.back(), r.trajectory.times.size());
  std::cout << fmt::format("  steps {}, rhs evaluations {}, Jacobian evaluations {}, error-test failures {}, "
                           "convergence failures {}, wall time {:.4f} s\n",
                           s.steps, s.rhs_evaluations, s.jacobian_evaluations, s.error_test_failures,
                           s.convergence_failures, s.wall_seconds);
  std::cout << fmt::format("  max |E(t) - E(0)| / |E(0)| = {:.3e}{}\n", drift,
                           conservative ? " (energy is conserved by this model: this is the integration error)"
                                        : " (the model does not conserve T + V)");
  if (m.num_constraints) std::cout << constraint_summary(m, r, false);
  if (!std::isnan(r.error_estimate))
    std::cout << fmt::format("  reference: Gragg–Bulirsch–Stoer extrapolation of order 16 in {}, macro step {:.3g} s; "
                             "estimated error {:.2e} (largest difference from the run at twice the step, relative to "
                             "each state's scale)\n", reference_scalar, r.reference_step, r.error_estimate);
}

// an explicit method on a stiff model: its steps are set by stability, not by accuracy
void stiffness_warning(const runtime::Problem& p, const std::vector<double>& x0, const runtime::SimulationSettings& s,
                       const runtime::SimulationResult& r) {
  if (!runtime::is_explicit_integrator(s.integrator)) return;
  double ratio = runtime::stiffness_ratio(p, x0, s.t_start);
  if (!(ratio > 1e3)) return;
  std::cerr << fmt::format("eomgen: warning: the model is stiff (stiffness ratio {:.2g} at the start: its fastest decay "
                           "is that many times quicker than its slowest motion); {} is limited by stability there, not by "
                           "accuracy, and took {} steps: cvode-bdf or arkode-dirk take far fewer\n",
                           ratio, s.integrator, r.statistics.steps);
}

}  // namespace

std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

int simulate_model(const SimulationOptions& o) {
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded)) return *status;
  if (!o.header_dir.empty()) {
    std::filesystem::create_directories(o.header_dir);
    write_file_atomically(o.header_dir + "/" + loaded.equations.model_name + ".hpp", loaded.header);
  }
  const eomgen_model_abi& m = *loaded.compiled->abi();
  runtime::Problem& problem = loaded.problem;
  std::vector<double> x0 = loaded.initial_state;
  std::vector<bool> given;
  if (!assign_states(m, o.initials, "--initial", x0, &given)) return exit_user_error;
  if (!(o.settings.t_end > o.settings.t_start) || !(o.settings.dt_out > 0) || !(o.settings.rtol > 0) ||
      !(o.settings.atol > 0) || o.settings.step < 0) {
    std::cerr << "eomgen: error: need --t-end > 0, --dt-out > 0, --rtol > 0, --atol > 0 and --step >= 0\n";
    return exit_user_error;
  }
  runtime::SimulationSettings settings = o.settings;
  settings.given_state = given;
  if (settings.integrator == "auto") {
    runtime::IntegratorChoice choice = runtime::choose_integrator(problem, x0, settings.t_start);
    settings.integrator = choice.integrator;
    std::cerr << fmt::format("eomgen: integrator {}: {} (--integrator chooses another)\n", choice.integrator, choice.reason);
  }
  std::cerr << fmt::format("eomgen: simulating {} with {} to t = {:g}\n", m.name, settings.integrator, o.settings.t_end);
  settings.baumgarte = o.stabilization == "both" || o.stabilization == "baumgarte";
  settings.projection = o.stabilization == "both" || o.stabilization == "projection";
  runtime::SimulationResult result;
  try {
    result = runtime::simulate(problem, x0, settings);
  } catch (const std::invalid_argument& why) {
    std::cerr << fmt::format("eomgen: error: --integrator {}: {}\n", settings.integrator, why.what());
    return exit_user_error;
  }
  for (const std::string& w : result.warnings) std::cerr << "eomgen: warning: " << w << "\n";
  stiffness_warning(problem, x0, settings, result);
  if (result.failed && result.trajectory.times.empty()) {
    std::cerr << fmt::format("eomgen: the simulation cannot start: {}\n", result.failure);
    return exit_numerical_failure;
  }
  bool conservative = m.conserves_energy_without_inputs &&
                      std::all_of(problem.inputs.begin(), problem.inputs.end(), [](double u) { return u == 0; });
  if (!o.csv.empty()) {
    if (std::string failure = write_file_atomically(o.csv, runtime::trajectory_csv(m, result.trajectory)); !failure.empty()) {
      std::cerr << "eomgen: " << failure << "\n";
      return exit_user_error;
    }
  }
  if (!o.plot.empty()) {
    if (std::string failure = runtime::draw_charts(m, result.trajectory, o.plot, conservative); !failure.empty())
      std::cerr << "eomgen: warning: no chart: " << failure << "\n";
    else
      std::cerr << fmt::format("eomgen: charts in {}{}\n", o.plot, conservative ? " and " + runtime::energy_chart_path(o.plot) : "");
  }
  print_summary(settings, m, result, conservative, o.json, loaded.compiled->reference_scalar);
  if (result.failed) {
    std::cerr << fmt::format("eomgen: the simulation failed: {}\n", result.failure);
    if (!o.csv.empty()) std::cerr << fmt::format("eomgen: {} holds the {} rows computed before the failure\n", o.csv, result.trajectory.times.size());
    return exit_numerical_failure;
  }
  return exit_success;
}

void add_simulation_options(CLI::App* cmd, SimulationOptions& o) {
  cmd->add_option("--t-end", o.settings.t_end, "End time [s] (default 10)");
  cmd->add_option("--dt-out", o.settings.dt_out, "Output interval [s] (default 0.01)");
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all{"auto"};
    for (const std::string& n : runtime::integrator_names()) all.push_back(n);
    return all;
  }();
  o.settings.integrator = "auto";
  cmd->add_option("--integrator", o.settings.integrator,
                  "auto (default: cvode-bdf for constrained or stiff models, else arkode-dp5; the choice is printed), "
                  "cvode-bdf, cvode-adams, arkode-dp5, arkode-verner, arkode-dirk, rk4, verlet, "
                  "ida (Lagrange I models, as a differential-algebraic system), reference (extrapolation in a wide scalar, "
                  "with its own error estimate)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--rtol", o.settings.rtol, "Relative tolerance (default 1e-8)");
  cmd->add_option("--atol", o.settings.atol, "Absolute tolerance (default 1e-10)");
  cmd->add_option("--step", o.settings.step, "Fixed step of rk4 and verlet [s] (default dt-out/10)");
  cmd->add_option("--stabilization", o.stabilization,
                  "Constrained models: both (default), baumgarte (Lagrange I), projection (after every step) or none")
      ->check(CLI::IsMember({"both", "baumgarte", "projection", "none"}));
  cmd->add_option("--baumgarte-alpha", o.settings.baumgarte_alpha, "Baumgarte's damping gain [1/s] (default: the model's, 10)");
  cmd->add_option("--baumgarte-beta", o.settings.baumgarte_beta, "Baumgarte's stiffness gain [1/s] (default: the model's, 10)");
  cmd->add_option("--set", o.sets, "Parameter or input value, one per flag: --set m=2.5")->allow_extra_args(false);
  cmd->add_option("--initial", o.initials, "Initial value, one per flag: --initial phi=0.3 --initial 'der(phi)=1'")->allow_extra_args(false);
  cmd->add_option("-o,--output", o.csv, "Trajectory CSV file");
  cmd->add_option("--plot", o.plot, "Chart of the coordinates (PNG); conservative models also get NAME_energy.png");
}

Command add_simulate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("simulate", "Generate, compile (cached) and simulate a model");
  auto o = std::make_shared<SimulationOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  add_simulation_options(cmd, *o);
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "Summary format: text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return simulate_model(*o);
  };
}

}  // namespace eomgen::cli
