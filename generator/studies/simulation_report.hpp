/// @file The summary and charts of `eomgen simulate`.
#pragma once

#include <optional>
#include <string>

#include "studies/exit_status.hpp"
#include "studies/simulation_run.hpp"
#include "simulation.hpp"

namespace eomgen::studies {

/// The run's statistics, energy change, the change of every first integral (`unforced`: no input acts), constraint residuals and reference estimate, as text or JSON.
void print_summary(const runtime::SimulationSettings& settings, const eomgen_model_abi& m, const runtime::SimulationResult& r,
                   bool conservative, bool unforced, bool json, const std::string& reference_scalar);

/// --plot-xy X,Y names two columns of the trajectory and needs --plot; prints the mistake.
std::optional<int> check_plot_xy(const SimulationOptions& o, const eomgen_model_abi& m);

/// The coordinates chart, and the energy, outputs and x-y charts where they apply.
void draw_all_charts(const SimulationOptions& o, const eomgen_model_abi& m, const runtime::Trajectory& trajectory,
                     bool conservative);

}  // namespace eomgen::studies
