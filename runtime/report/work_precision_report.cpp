#include "report/work_precision_report.hpp"

#include "report/gnuplot.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>

#include <fmt/format.h>

namespace eomgen::runtime {

namespace {


std::vector<std::string> integrators_of(const std::vector<WorkPrecisionRun>& runs) {
  std::vector<std::string> names;
  for (const WorkPrecisionRun& r : runs)
    if (names.empty() || names.back() != r.integrator) names.push_back(r.integrator);
  return names;
}

std::string setting(const WorkPrecisionRun& r) {
  return r.step > 0 ? fmt::format("step {:.3g} s", r.step) : fmt::format("rtol {:.0e}", r.tolerance);
}


// one chart as PNG and SVG from the same plot command
std::string both_terminals(const std::string& path_stem, const std::string& settings, const std::string& plot) {
  std::string text;
  for (const char* terminal : {"pngcairo size 1000,600 noenhanced", "svg size 1000,600 noenhanced"}) {
    std::string extension = std::string(terminal).rfind("svg", 0) == 0 ? "svg" : "png";
    text += fmt::format("set terminal {}\nset output {}\n{}\n{}\n", terminal, gnuplot_quoted(path_stem + "." + extension),
                        settings, plot);
  }
  return text;
}

// the ratio of the fastest decay rate (largest −Re λ of the Jacobian) to the slowest rate
// (smallest nonzero |λ|) means something only when it is large
std::string stiffness_text(double ratio) {
  if (!(ratio >= 1)) return "not stiff (no mode decays faster than the slowest motion)";
  if (ratio < 1e3) return fmt::format("not stiff (fastest decay rate over slowest rate {:.3g})", ratio);
  return fmt::format("stiff (fastest decay rate, largest -Re of the Jacobian's eigenvalues, over the slowest rate, "
                     "smallest nonzero |eigenvalue|: {:.3g})", ratio);
}

}  // namespace

std::vector<double> verdict_levels(const std::vector<WorkPrecisionRun>& runs) {
  double best = INFINITY;
  for (const WorkPrecisionRun& r : runs)
    if (std::isfinite(r.error)) best = std::min(best, r.error);
  std::vector<double> levels;
  for (int k = 2; k <= 14 && std::pow(10.0, -k) >= best; k += 2) levels.push_back(std::pow(10.0, -k));
  return levels;
}

std::string work_precision_markdown(const std::string& model, const WorkPrecision& w, const WorkPrecisionSettings& s,
                                    const std::string& reference_scalar) {
  std::string out = fmt::format("# Work against precision: {}\n\n", model);
  out += fmt::format(
      "From t = {:g} to {:g} s; the error of a run is the largest difference from the reference over the output "
      "times (every {:g} s), each state relative to its own scale. Reference: order-16 extrapolation in {}, estimated "
      "error {:.1e}. Stiffness at the start: {}.\n\n",
      s.t_start, s.t_end, s.dt_out, reference_scalar, w.reference_error_estimate, stiffness_text(w.stiffness_ratio));
  std::vector<double> levels = verdict_levels(w.runs);
  std::vector<const WorkPrecisionRun*> best = cheapest_at(w.runs, levels);
  out += "## Verdict\n\n| accuracy | cheapest method | setting | CPU time [s] | rhs evaluations |\n| --- | --- | --- | --- | --- |\n";
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (!best[i]) continue;
    out += fmt::format("| {:.0e} | {} | {} | {:.3g} | {} |\n", levels[i], best[i]->integrator, setting(*best[i]),
                       best[i]->cpu_seconds, best[i]->rhs_evaluations);
  }
  std::set<std::string> winners;
  for (const WorkPrecisionRun* b : best)
    if (b) winners.insert(b->integrator);
  std::string names;
  for (const std::string& n : winners) names += (names.empty() ? "" : ", ") + n;
  out += fmt::format("\nIn short: for this model the cheapest methods are {}.\n", names.empty() ? "(none reached 1e-2)" : names);
  // the order is read off above the floor every method reaches (roundoff amplified by the model)
  double floor = INFINITY;
  for (const WorkPrecisionRun& r : w.runs)
    if (std::isfinite(r.error) && r.error > 0) floor = std::min(floor, r.error);
  for (const char* fixed : {"rk4", "verlet", "gauss-legendre"}) {
    double order = observed_order(w.runs, fixed, 10 * floor, 1e-3);
    if (std::isfinite(order))
      out += fmt::format("Observed order of {} (slope of log error against log step, errors from {:.0e} to 1e-3): {:.2f}.\n",
                         fixed, 10 * floor, order);
  }
  out += "\n## Runs\n\n| integrator | setting | error | CPU time [s] | rhs evaluations | Jacobian evaluations | steps |\n"
         "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const WorkPrecisionRun& r : w.runs)
    out += fmt::format("| {} | {} | {} | {:.3g} | {} | {} | {} |\n", r.integrator, setting(r),
                       std::isfinite(r.error) ? fmt::format("{:.2e}", r.error) : "failed", r.cpu_seconds,
                       r.rhs_evaluations, r.jacobian_evaluations, r.steps);
  if (!w.energy.empty()) {
    out += fmt::format("\n## Energy over {:g} s (rtol {:.0e}; fixed steps {:g} s)\n\n| integrator | largest relative energy "
                       "error |\n| --- | --- |\n",
                       s.energy_horizon, s.energy_tolerance, s.energy_step);
    for (const EnergyHistory& h : w.energy) {
      double largest = 0;
      for (double e : h.relative_error) largest = std::max(largest, e);
      out += fmt::format("| {} | {:.2e}{} |\n", h.integrator, largest, h.failure.empty() ? "" : " (failed)");
    }
  }
  if (!w.horizons.empty()) {
    out += fmt::format("\n## Accuracy horizon ({})\n\nThe time until the runs at rtol and rtol/10 differ by 1e-2: beyond "
                       "it the trajectory is not known to two digits.\n\n| rtol | horizon [s] |\n| --- | --- |\n",
                       s.horizon_integrator);
    for (const AccuracyHorizon& h : w.horizons)
      out += fmt::format("| {:.0e} | {:.3g}{} |\n", h.tolerance, h.horizon, h.horizon >= s.t_end * (1 - 1e-9) ? " (the whole run)" : "");
    if (std::isfinite(w.lyapunov_estimate))
      out += fmt::format("\nEach tenfold tighter tolerance buys ln(10)/λ more seconds: the horizons give λ ≈ {:.3g} 1/s, "
                         "the largest Lyapunov exponent of this motion.\n", w.lyapunov_estimate);
  }
  out += "\nCharts: work_precision.png (error against CPU time), error_vs_evaluations.png, energy_error.png (conservative models); also as SVG.\n";
  return out;
}

std::string work_precision_csv(const WorkPrecision& w) {
  std::string out = "integrator,rtol,step,error,cpu_seconds,rhs_evaluations,jacobian_evaluations,steps\n";
  for (const WorkPrecisionRun& r : w.runs)
    out += fmt::format("{},{:.3g},{:.6g},{:.6g},{:.6g},{},{},{}\n", r.integrator, r.tolerance, r.step, r.error, r.cpu_seconds,
                       r.rhs_evaluations, r.jacobian_evaluations, r.steps);
  return out;
}

std::string energy_csv(const WorkPrecision& w) {
  if (w.energy.empty()) return {};
  std::string out = "t";
  for (const EnergyHistory& h : w.energy) out += "," + h.integrator;
  out += "\n";
  for (std::size_t k = 0; k < w.energy.front().times.size(); ++k) {
    out += fmt::format("{:.6g}", w.energy.front().times[k]);
    for (const EnergyHistory& h : w.energy) out += k < h.relative_error.size() ? fmt::format(",{:.6g}", h.relative_error[k]) : ",nan";
    out += "\n";
  }
  return out;
}

std::string horizons_csv(const WorkPrecision& w) {
  if (w.horizons.empty()) return {};
  std::string out = "rtol,horizon\n";
  for (const AccuracyHorizon& h : w.horizons) out += fmt::format("{:.3g},{:.6g}\n", h.tolerance, h.horizon);
  return out;
}

std::string draw_work_precision(const std::string& model, const WorkPrecision& w, const std::string& directory) {
  std::string data = directory + "/work_precision.data.tmp";
  std::vector<std::string> names = integrators_of(w.runs);
  {
    std::ofstream out(data);
    for (const std::string& name : names) {
      for (const WorkPrecisionRun& r : w.runs)
        if (r.integrator == name && std::isfinite(r.error))
          out << fmt::format("{:.6g} {:.6g} {}\n", r.cpu_seconds, std::max(r.error, 1e-17), r.rhs_evaluations);
      out << "\n\n";
    }
  }
  auto curves = [&](const char* columns) {
    std::string plot = "plot ";
    for (std::size_t i = 0; i < names.size(); ++i)
      plot += fmt::format("{}{} index {} using {} with linespoints lw 2 pt 7 title {}", i ? ", " : "", gnuplot_quoted(data), i,
                          columns, gnuplot_quoted(names[i]));
    return plot;
  };
  std::string common = "set grid\nset logscale xy\nset format x '%.0e'\nset format y '%.0e'\nset key outside right\n"
                       "set ylabel 'error (largest, relative to each state)'";
  std::string script =
      both_terminals(directory + "/work_precision",
                     common + fmt::format("\nset title {}\nset xlabel 'CPU time [s]'", gnuplot_quoted(model + ": work against precision")),
                     curves("1:2")) +
      both_terminals(directory + "/error_vs_evaluations",
                     common + fmt::format("\nset title {}\nset xlabel 'right-hand-side evaluations'",
                                          gnuplot_quoted(model + ": error against right-hand sides")),
                     curves("3:2"));
  std::string energy = directory + "/energy.data.tmp";
  if (!w.energy.empty()) {
    std::ofstream out(energy);
    for (const EnergyHistory& h : w.energy) {
      for (std::size_t k = 0; k < h.times.size(); ++k) out << fmt::format("{:.6g} {:.6g}\n", h.times[k], h.relative_error[k]);
      out << "\n\n";
    }
    out.close();
    std::string plot = "plot ";
    for (std::size_t i = 0; i < w.energy.size(); ++i)
      plot += fmt::format("{}{} index {} using 1:2 with lines lw 2 title {}", i ? ", " : "", gnuplot_quoted(energy), i,
                          gnuplot_quoted(w.energy[i].integrator));
    script += both_terminals(directory + "/energy_error",
                             fmt::format("set grid\nunset logscale\nset logscale y\nset format x '%g'\nset format y '%.0e'\nset key outside right\n"
                                         "set title {}\nset xlabel 't [s]'\nset ylabel '|E(t) - E(0)| / |E(0)|'",
                                         gnuplot_quoted(model + ": energy error over a long run")),
                             plot);
  }
  std::string horizon = directory + "/horizon.data.tmp";
  if (!w.horizons.empty()) {
    std::ofstream out(horizon);
    for (const AccuracyHorizon& h : w.horizons) out << fmt::format("{:.6g} {:.6g}\n", h.tolerance, h.horizon);
    out.close();
    script += both_terminals(directory + "/accuracy_horizon",
                             fmt::format("set grid\nunset logscale\nset logscale x\nset format x '%.0e'\nset format y '%g'\n"
                                         "set key off\nset title {}\nset xlabel 'relative tolerance'\n"
                                         "set ylabel 'accuracy horizon [s]'",
                                         gnuplot_quoted(model + ": time until rtol and rtol/10 differ by 1e-2")),
                             fmt::format("plot {} using 1:2 with linespoints lw 2 pt 7", gnuplot_quoted(horizon)));
  }
  std::string failure = run_gnuplot(script, directory + "/work_precision");
  std::remove(horizon.c_str());
  std::remove(data.c_str());
  std::remove(energy.c_str());
  return failure;
}

}  // namespace eomgen::runtime
