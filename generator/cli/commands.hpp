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

#include "common/diagnostic.hpp"
#include "model/model.hpp"
#include "studies/exit_status.hpp"
#include "studies/simulation_run.hpp"

namespace eomgen::cli {

// the front ends speak the studies' language: options, one study, its exit status
using namespace eomgen::studies;

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

/// simulate's options (times, integrator, tolerances, --set, --initial, inputs, scene, CSV, charts).
void add_simulation_options(CLI::App* cmd, SimulationOptions& o);
/// simulate's and animate's --trace and --axes.
void add_animation_options(CLI::App* cmd, SimulationOptions& o);
/// Derives `model_path` and writes NAME.hpp into `directory`, or to `header_file` when that is not empty;
/// with `split_above_kb`, also the split units of its functions of that many KB (emit/split_units.hpp);
/// its rhs solves for q'' in `forward_dynamics`, eomgen's choice unless one form is asked for.
int generate_header(const std::string& model_path, const std::string& directory, const std::string& header_file,
                    const std::string& variant = "", const std::string& scene = "",
                    std::optional<std::size_t> split_above_kb = std::nullopt,
                    ForwardDynamics forward_dynamics = ForwardDynamics::chosen);

/// The model `eomgen run` uses when none is named.
std::string default_model_path();

/// Derives `model_path` and writes it in `format` to `output` (stdout when empty); with
/// `reduce`, the Routh-reduced equations with those cyclic coordinates eliminated; with
/// `written_out` (and `linearize`), the equations multiplied out in q.
int derive_and_write(const std::string& model_path, const std::string& format, const std::string& output,
                     bool linearize = false, const std::vector<std::string>& reduce = {}, const std::string& variant = "",
                     bool written_out = false);

}  // namespace eomgen::cli
