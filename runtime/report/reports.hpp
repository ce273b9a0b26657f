/// @file Reports of a simulation: the trajectory as CSV, and charts drawn by gnuplot.
#pragma once

#include <string>

#include "analyse/eigenvalue_sweep.hpp"
#include "analyse/ensemble.hpp"
#include "analyse/stability_map.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

/// The CSV of a run, written as it is computed: the header line (t, the coordinates, the
/// velocities, T + V, the outputs, for constrained models the multipliers and the residuals,
/// then the first integrals I[name]), and one line per row, numbers with 17 significant digits.
std::string trajectory_csv_header(const eomgen_model_abi& model);
std::string trajectory_csv_rows(const eomgen_model_abi& model, const Trajectory& rows);

/// Draws the coordinates over time into `png_path`, and when `energy_chart` is set
/// the relative energy error |E(t) − E(0)|/|E(0)| into the same name with _energy.
/// Returns an empty string on success, else what went wrong.
std::string draw_charts(const eomgen_model_abi& model, const Trajectory& trajectory, const std::string& png_path,
                        bool energy_chart);

/// Draws a stability map: the stability degree as colours about zero, its zero contour,
/// and when `symbolic_margin` is given (one value per grid point, > 0 where every
/// symbolic condition holds) the symbolic boundary over it.
std::string draw_stability_map(const StabilityMap& map, const std::string& x_name, const std::string& y_name,
                               const std::string& title, const std::vector<double>& symbolic_margin,
                               const std::string& png_path);

/// Draws the eigenvalues against the swept parameter, with the crossings of the
/// imaginary axis and the stable intervals.
std::string draw_eigenvalue_sweep(const EigenvalueSweep& sweep, const std::string& parameter, const std::string& title,
                                  const std::string& png_path);

/// An ensemble's signals over time, one panel each: the band between the outermost
/// quantiles, the band of one standard deviation about the mean, the mean, and the median
/// when it is among the quantiles.
std::string draw_ensemble_bands(const std::string& title, const std::vector<double>& times,
                                const std::vector<SignalBands>& bands, const std::vector<double>& probabilities,
                                const std::string& png_path);

/// FILE.png with `suffix` before the extension: the companion charts of `png_path`.
std::string chart_path(const std::string& png_path, const std::string& suffix);

/// The path of the energy chart that belongs to `png_path`.
std::string energy_chart_path(const std::string& png_path);

/// The paths of the outputs chart (NAME_outputs.png) and the x–y chart (NAME_xy.png).
std::string outputs_chart_path(const std::string& png_path);
std::string xy_chart_path(const std::string& png_path);

/// The values over the run of a column of the trajectory CSV by its header name (t, a
/// coordinate, a velocity, energy, an output); false when there is none of that name.
bool trajectory_column(const eomgen_model_abi& model, const Trajectory& trajectory, const std::string& name,
                       std::vector<double>& out);

/// The model's outputs over time.
std::string draw_outputs_chart(const eomgen_model_abi& model, const Trajectory& trajectory, const std::string& png_path);

/// `y_name` against `x_name` (equal scales), with the start marked.
std::string draw_xy_chart(const eomgen_model_abi& model, const Trajectory& trajectory, const std::string& x_name,
                          const std::string& y_name, const std::string& png_path);

}  // namespace eomgen::runtime
