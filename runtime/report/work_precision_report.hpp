/// @file The report of `eomgen bench`: a markdown table with the verdict, the runs as
/// CSV, and the charts (work against precision, error against right-hand sides, and
/// the long-horizon energy error), each as PNG and SVG.
#pragma once

#include <string>
#include <vector>

#include "analyse/work_precision.hpp"

namespace eomgen::runtime {

/// The accuracies the verdict is given for: 1e-2, 1e-4, …
std::vector<double> verdict_levels(const std::vector<WorkPrecisionRun>& runs);

std::string work_precision_markdown(const std::string& model, const WorkPrecision& result, const WorkPrecisionSettings& settings,
                                    const std::string& reference_scalar);
std::string work_precision_csv(const WorkPrecision& result);
/// The long-horizon energy errors, one column per integrator (empty without them).
std::string energy_csv(const WorkPrecision& result);
/// rtol, horizon (empty without accuracy horizons).
std::string horizons_csv(const WorkPrecision& result);

/// Writes DIR/work_precision.{png,svg}, DIR/error_vs_evaluations.{png,svg} and, with energy
/// histories, DIR/energy_error.{png,svg}. Empty on success, else what went wrong.
std::string draw_work_precision(const std::string& model, const WorkPrecision& result, const std::string& directory);

}  // namespace eomgen::runtime
