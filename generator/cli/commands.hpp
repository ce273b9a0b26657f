/// @file The subcommands of the eomgen command line; each registers its
/// options on the app and returns the exit status when run.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "analyse/equilibrium.hpp"
#include "common/diagnostic.hpp"
#include "report/animation.hpp"
#include "simulation.hpp"

namespace eomgen::cli {

/// Exit statuses of DESIGN.md.
enum ExitStatus { exit_success = 0, exit_internal_error = 1, exit_user_error = 2, exit_numerical_failure = 3 };

using Command = std::function<int()>;

/// A number > 0 (or >= 0), said in words: CLI11's own range checks print the largest double in
/// full, 300 digits of it.
inline CLI::Validator positive_number(bool zero_allowed = false) {
  return CLI::Validator(
      [zero_allowed](std::string& text) -> std::string {
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        bool number = end != text.c_str() && *end == '\0' && std::isfinite(v);
        if (number && (v > 0 || (zero_allowed && v == 0))) return {};
        return "'" + text + "' is not a " + (zero_allowed ? "number >= 0" : "positive number");
      },
      zero_allowed ? "NUMBER >= 0" : "NUMBER > 0");
}

Command add_derive_command(CLI::App& app);
Command add_generate_command(CLI::App& app);
Command add_simulate_command(CLI::App& app);
Command add_stability_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_diff_command(CLI::App& app);
Command add_check_integral_command(CLI::App& app);
Command add_linear_command(CLI::App& app);
Command add_scene_command(CLI::App& app);
Command add_fmu_command(CLI::App& app);
Command add_ensemble_command(CLI::App& app);
Command add_import_command(CLI::App& app);
Command add_animate_command(CLI::App& app);

struct LoadedProblem;
/// Why stability and sweep cannot analyse this model (Lagrange I always; symbolic
/// conditions of Appell models), printed; nothing when they can.
std::optional<int> stability_refusal(const LoadedProblem& loaded, const std::string& model, bool symbolic,
                                      bool on_manifold);

struct PeriodicOptions {
  std::vector<std::string> at;
  std::string symbolic;
  double period = 0;  // given with --period; 0: found from the model
  bool json = false;
};
/// For a model whose equations depend on time: the refusal, or the Floquet analysis,
/// printed, and its exit status; nothing for an autonomous model.
std::optional<int> periodic_stability(const LoadedProblem& loaded, const PeriodicOptions& options);

/// `eomgen bench MODEL -o DIRECTORY` with the default settings.
int bench_model(const std::string& model, const std::string& directory);
/// `eomgen stability MODEL` (equilibrium searched from the initial values), as text.
int stability_of_model(const std::string& model);

struct SimulationOptions {
  std::string model;
  runtime::SimulationSettings settings;
  std::vector<std::string> sets, initials;
  std::vector<std::string> input_signals;  // --input NAME=EXPRESSION in t
  std::string input_file;                  // --input-file table.csv
  std::string csv, plot, header_dir;
  std::string plot_xy;  // "X,Y": also Y against X
  std::string stabilization = "both";
  std::string reference_scalar;  // filled in by simulate_model from the compiled model  // constrained models: both, baumgarte, projection or none
  bool json = false;
  std::string scene, variant;          // --scene NAME, --variant NAME
  bool t_end_given = false, dt_out_given = false;  // a scene's times give way to --t-end, --dt-out
  double max_rows = 1e6;  // output rows a run may keep in memory (--max-rows)
  std::string animation;           // --animate FILE.html (animate: -o)
  std::vector<std::string> trace;  // --trace NAME: bodies whose paths the animation draws
  bool axes = false;               // --axes
  bool animate_only = false;
  bool animation_if_drawn = false;  // `eomgen run`: no page (and no error) for a model that draws nothing       // `eomgen animate`: the page is the result (named after the model by default)
};

/// Derives, generates, compiles (cached) and simulates; writes the CSV and charts asked for.
int simulate_model(const SimulationOptions& options);

/// simulate's options (times, integrator, tolerances, --set, --initial, inputs, scene, CSV, charts).
void add_simulation_options(CLI::App* cmd, SimulationOptions& o);
/// simulate's and animate's --trace and --axes.
void add_animation_options(CLI::App* cmd, SimulationOptions& o);
/// Writes the animation page of a run to o.animation; the exit status when it cannot.
std::optional<int> write_animation(const runtime::AnimationRecorder& recorder, const SimulationOptions& o);

/// Prints a derivation's diagnostics and the closing "nothing written" line; true when there were any.
bool report_diagnostics(const Diagnostics& diagnostics, const std::string& model_path);

/// The equilibrium of `problem`: checked when --at names one, else searched for.
/// Returns the exit status when there is none.
/// `initial` is the model's initial state (with --set applied): where the search starts,
/// and the coordinates --at does not name.
std::optional<int> equilibrium_of(const runtime::Problem& problem, const std::vector<std::string>& at,
                                  const std::vector<double>& initial, runtime::Equilibrium& out);

/// Derives `model_path` and writes NAME.hpp into `directory`, or to `header_file` when that is not empty;
/// with `split_above_kb`, also the split units of its functions of that many KB (emit/split_units.hpp).
int generate_header(const std::string& model_path, const std::string& directory, const std::string& header_file,
                    const std::string& variant = "", const std::string& scene = "",
                    std::optional<std::size_t> split_above_kb = std::nullopt);

/// The model `eomgen run` uses when none is named.
std::string default_model_path();

/// Derives `model_path` and writes it in `format` to `output` (stdout when empty); with
/// `reduce`, the Routh-reduced equations with those cyclic coordinates eliminated.
int derive_and_write(const std::string& model_path, const std::string& format, const std::string& output,
                     bool linearize = false, const std::vector<std::string>& reduce = {}, const std::string& variant = "");

}  // namespace eomgen::cli
