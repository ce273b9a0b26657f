/// @file What `eomgen simulate` reports besides the CSV: the summary (statistics,
/// energy change, constraints, the reference's error estimate) and the charts.
#include "studies/simulation_report.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "analyse/conservation.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"
#include "report/reports.hpp"

namespace eomgen::studies {

// none where E(0) = 0 (at rest, its forces without a potential): the change over 1e-300 had printed
// as a drift of 4.8e305
static double relative_energy_drift(const runtime::RunSummary& run) {
  return run.first_energy != 0 ? run.largest_energy_change / std::abs(run.first_energy) : NAN;
}

static std::string constraint_summary(const eomgen_model_abi& m, const runtime::SimulationResult& r, bool json) {
  const std::vector<double>& largest = r.summary.largest_multipliers;
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

// ball and free joints: whether the quaternions were kept unit, and how far |q| strayed from 1
static std::string quaternion_summary(const eomgen_model_abi& m, const runtime::SimulationResult& r, bool json) {
  const std::string& when = r.quaternions_normalized;
  if (json)
    return fmt::format(", \"quaternions\": {{\"count\": {}, \"normalized\": {}, \"max_correction\": {}, "
                       "\"max_norm_error\": {}}}",
                       m.num_quaternions, when.empty() ? "null" : json_quoted(when), json_number(r.largest_quaternion_correction),
                       json_number(r.largest_quaternion_norm_error));
  if (!when.empty())
    return fmt::format("  quaternions: normalized {} (largest correction of |q| {:.3e})\n", when,
                       r.largest_quaternion_correction);
  return fmt::format("  quaternions: not normalized (the projection is off); largest ||q| - 1| over the output times "
                     "{:.3e} (the rotation is that of q/|q|, so the motion does not depend on it)\n",
                     r.largest_quaternion_norm_error);
}

// the change of every first integral over the run; with inputs acting they need not be constant
static std::string first_integral_summary(const eomgen_model_abi& m, const runtime::RunSummary& run, bool unforced, bool json) {
  std::vector<runtime::FirstIntegralDrift> drift = runtime::first_integral_drift(m, run);
  if (json) {
    std::string list;
    for (const runtime::FirstIntegralDrift& d : drift)
      list += fmt::format("{}{{\"name\": {}, \"initial\": {}, \"max_abs_change\": {}, \"relative_change\": {}}}",
                          list.empty() ? "" : ", ", json_quoted(d.name), json_number(d.initial), json_number(d.largest_change),
                          json_number(d.relative_change));
    return fmt::format(", \"first_integrals_conserved\": {}, \"first_integrals\": [{}]", unforced ? "true" : "false", list);
  }
  if (drift.empty()) return "";
  std::string out = unforced ? "  first integrals (constant in the exact motion: their change is the integration error):\n"
                             : "  first integrals (the inputs act, so they need not stay constant):\n";
  for (const runtime::FirstIntegralDrift& d : drift)
    out += fmt::format("    {}: I(0) = {:.10g}, max |I(t) - I(0)| = {:.3e}{}\n", d.name, d.initial, d.largest_change,
                       std::isnan(d.relative_change) ? std::string() : fmt::format(" ({:.3e} of |I(0)|)", d.relative_change));
  return out;
}

void print_summary(const runtime::SimulationSettings& settings, const eomgen_model_abi& m, const runtime::SimulationResult& r,
                   bool conservative, bool unforced, bool json, const std::string& reference_scalar) {
  const runtime::SolverStatistics& s = r.statistics;
  double drift = relative_energy_drift(r.summary);
  if (json) {
    std::string failure = r.failed ? fmt::format("{{\"time\": {:.17g}, \"flag\": {}, \"reason\": {}}}", r.failure_time,
                                                 r.solver_flag, json_quoted(r.failure))
                                   : "null";
    std::cout << fmt::format(
        "{{\"model\": \"{}\", \"integrator\": \"{}\", \"t_start\": {:.17g}, \"t_end\": {:.17g}, \"rows\": {}, "
        "\"statistics\": {{\"steps\": {}, \"rhs_evaluations\": {}, \"jacobian_evaluations\": {}, "
        "\"error_test_failures\": {}, \"convergence_failures\": {}, \"wall_seconds\": {:.6g}}}, "
        "\"conserves_energy\": {}, \"relative_energy_drift\": {}{}{}{}{}, \"failure\": {}}}\n",
        m.name, settings.integrator, settings.t_start, r.summary.last_time, r.summary.rows, s.steps,
        s.rhs_evaluations, s.jacobian_evaluations, s.error_test_failures, s.convergence_failures, s.wall_seconds,
        conservative ? "true" : "false", json_number(drift), first_integral_summary(m, r.summary, unforced, true),
        m.num_constraints ? constraint_summary(m, r, true) : "", m.num_quaternions ? quaternion_summary(m, r, true) : "",
        std::isnan(r.error_estimate) ? std::string()
                                     : fmt::format(", \"reference_error_estimate\": {:.6g}, \"reference_step\": {:.6g}",
                                                   r.error_estimate, r.reference_step),
        failure);
    return;
  }
  std::cout << fmt::format("{}: {} from t = {:g} to {:.9g}, {} output rows\n", m.name, settings.integrator,
                           settings.t_start, r.summary.last_time, r.summary.rows);
  std::cout << fmt::format("  steps {}, rhs evaluations {}, Jacobian evaluations {}, error-test failures {}, "
                           "convergence failures {}, wall time {:.4f} s\n",
                           s.steps, s.rhs_evaluations, s.jacobian_evaluations, s.error_test_failures,
                           s.convergence_failures, s.wall_seconds);
  std::string energy = r.summary.first_energy == 0
                           ? fmt::format("max |E(t) - E(0)| = {:.3e} (E(0) = 0: no relative drift)", r.summary.largest_energy_change)
                           : fmt::format("max |E(t) - E(0)| / |E(0)| = {:.3e}", drift);
  std::cout << fmt::format("  {}{}\n", energy,
                           conservative ? " (energy is conserved by this model: this is the integration error)"
                                        : " (the model does not conserve T + V)");
  std::cout << first_integral_summary(m, r.summary, unforced, false);
  if (m.num_constraints) std::cout << constraint_summary(m, r, false);
  if (m.num_quaternions) std::cout << quaternion_summary(m, r, false);
  if (!std::isnan(r.error_estimate))
    std::cout << fmt::format("  reference: Gragg–Bulirsch–Stoer extrapolation of order 16 in {}, macro step {:.3g} s; "
                             "estimated error {:.2e} (largest difference from the run at twice the step, relative to "
                             "each state's scale)\n", reference_scalar, r.reference_step, r.error_estimate);
}

// --plot-xy X,Y names two columns of the trajectory and needs --plot
std::optional<int> check_plot_xy(const SimulationOptions& o, const eomgen_model_abi& m) {
  if (o.plot_xy.empty()) return std::nullopt;
  std::size_t comma = o.plot_xy.find(',');
  std::vector<std::string> names{"t", "energy"};
  names.insert(names.end(), m.state_names, m.state_names + m.num_states);
  names.insert(names.end(), m.output_names, m.output_names + m.num_outputs);
  if (o.plot.empty() || comma == std::string::npos) {
    std::cerr << fmt::format("eomgen: error: --plot-xy {}: expected X,Y with --plot FILE.png (the chart is FILE_xy.png)\n",
                             o.plot_xy);
    return exit_user_error;
  }
  for (const std::string& name : {o.plot_xy.substr(0, comma), o.plot_xy.substr(comma + 1)})
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::cerr << fmt::format("eomgen: error: --plot-xy: '{}' is not a column of the trajectory; {}\n", name,
                               suggest(name, names, "columns"));
      return exit_user_error;
    }
  return std::nullopt;
}

void draw_all_charts(const SimulationOptions& o, const eomgen_model_abi& m, const runtime::Trajectory& trajectory,
                     bool conservative) {
  std::vector<std::string> drawn;
  auto report = [&drawn](const std::string& failure, const std::string& path) {
    if (failure.empty()) drawn.push_back(path);
    else std::cerr << "eomgen: warning: no chart " << path << ": " << failure << "\n";
  };
  report(runtime::draw_charts(m, trajectory, o.plot, conservative), o.plot);
  if (conservative) drawn.push_back(runtime::energy_chart_path(o.plot));
  if (m.num_outputs)
    report(runtime::draw_outputs_chart(m, trajectory, runtime::outputs_chart_path(o.plot)), runtime::outputs_chart_path(o.plot));
  if (!o.plot_xy.empty()) {
    std::size_t comma = o.plot_xy.find(',');
    report(runtime::draw_xy_chart(m, trajectory, o.plot_xy.substr(0, comma), o.plot_xy.substr(comma + 1),
                                  runtime::xy_chart_path(o.plot)),
           runtime::xy_chart_path(o.plot));
  }
  std::string list;
  for (const std::string& path : drawn) list += (list.empty() ? "" : ", ") + path;
  if (!list.empty()) std::cerr << "eomgen: charts in " << list << "\n";
}

}  // namespace eomgen::studies
