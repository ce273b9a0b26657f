#include "analyse/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/accuracy.hpp"
#include "analyse/first_order_form.hpp"
#include "analyse/state_tolerances.hpp"
#include "analyse/system_scales.hpp"

namespace eomgen::runtime {

namespace {

bool fixed_step(const std::string& name) { return is_fixed_step_integrator(name); }

double cpu_now() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// runs a short simulation several times so that its CPU time is not just clock resolution
SimulationResult timed(const Problem& p, const std::vector<double>& x0, const SimulationSettings& s, double& seconds) {
  double start = cpu_now();
  SimulationResult r = simulate(p, x0, s);
  seconds = cpu_now() - start;
  int repeats = 1;
  while (seconds * repeats < 0.05 && repeats < 64 && !r.failed) {
    double again = cpu_now();
    simulate(p, x0, s);
    seconds = std::min(seconds, cpu_now() - again);
    ++repeats;
  }
  return r;
}

WorkPrecisionRun measure(const Problem& p, const std::vector<double>& x0, SimulationSettings s, const Trajectory& reference) {
  WorkPrecisionRun run;
  run.integrator = s.integrator;
  run.tolerance = fixed_step(s.integrator) ? 0 : s.rtol;
  run.step = fixed_step(s.integrator) ? s.step : 0;
  SimulationResult r = timed(p, x0, s, run.cpu_seconds);
  run.rhs_evaluations = r.statistics.rhs_evaluations;
  run.jacobian_evaluations = r.statistics.jacobian_evaluations;
  run.steps = r.statistics.steps;
  run.error = r.failed ? NAN : trajectory_error(r.trajectory.states, reference.states);
  run.failure = r.failure;
  return run;
}

EnergyHistory energy_history(const Problem& p, const std::vector<double>& x0, const WorkPrecisionSettings& w,
                             const std::string& integrator) {
  SimulationSettings s;
  s.t_start = w.t_start;
  s.t_end = w.t_start + w.energy_horizon;
  s.dt_out = w.energy_horizon / 500;
  s.integrator = integrator;
  s.rtol = w.energy_tolerance;
  s.atol = w.energy_tolerance / 100;
  s.state_atol = state_absolute_tolerances(p, x0, s.rtol, s.atol);
  s.step = w.energy_step;
  s.max_steps = 10'000'000;
  SimulationResult r = simulate(p, x0, s);
  EnergyHistory h;
  h.integrator = integrator;
  h.failure = r.failure;
  double e0 = r.trajectory.energies.front();
  for (std::size_t k = 1; k < r.trajectory.times.size(); ++k) {
    h.times.push_back(r.trajectory.times[k]);
    h.relative_error.push_back(std::max(std::abs(r.trajectory.energies[k] - e0) / std::max(std::abs(e0), 1e-300), 1e-17));
  }
  return h;
}

// the first output time at which two trajectories differ by more than 1e-2 (states relative to
// the scales of the second, as trajectory_error takes them), or their end when they never do
double parting_time(const Trajectory& a, const Trajectory& b) {
  std::vector<double> scales = state_scales(b.states);
  std::size_t rows = std::min(a.times.size(), b.times.size());
  for (std::size_t k = 0; k < rows; ++k)
    if (!(row_error(a.states[k], b.states[k], scales) <= 1e-2)) return a.times[k];
  return a.times[rows - 1];
}

void accuracy_horizons(const Problem& p, const std::vector<double>& x0, const WorkPrecisionSettings& w, WorkPrecision& out,
                       const std::function<void(const std::string&)>& progress) {
  SimulationSettings s;
  s.t_start = w.t_start;
  s.t_end = w.t_end;
  s.dt_out = w.dt_out;
  s.integrator = w.horizon_integrator;
  s.max_steps = 2'000'000;
  for (double tolerance : w.tolerances) {
    s.rtol = tolerance, s.atol = tolerance / 100;
    s.state_atol = state_absolute_tolerances(p, x0, s.rtol, s.atol);
    SimulationResult loose = simulate(p, x0, s);
    s.rtol = tolerance / 10, s.atol = tolerance / 1000;
    s.state_atol = state_absolute_tolerances(p, x0, s.rtol, s.atol);
    SimulationResult tight = simulate(p, x0, s);
    out.horizons.push_back({tolerance, parting_time(loose.trajectory, tight.trajectory)});
    progress(fmt::format("accuracy horizon at rtol {:.0e} ({}): {:.3g} s", tolerance, s.integrator, out.horizons.back().horizon));
  }
  // horizon ≈ a + b·log10(1/tol) for a chaotic flow with errors growing like e^(λt): λ = ln 10 / b
  std::vector<double> x, y;
  for (const AccuracyHorizon& h : out.horizons)
    if (h.horizon < w.t_end * (1 - 1e-9)) x.push_back(-std::log10(h.tolerance)), y.push_back(h.horizon);
  if (x.size() >= 3) {
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / x.size();
    for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    if (sxy > 0) out.lyapunov_estimate = std::log(10.0) / (sxy / sxx);
  }
}

}  // namespace

double stiffness_ratio(const Problem& p, const std::vector<double>& x0, double t0) {
  return stiffness_ratio_of(state_jacobian(p, t0, x0));
}

double stiffness_ratio_of(const Eigen::MatrixXd& J) {
  if (!J.allFinite()) return NAN;
  Eigen::MatrixXd B = balanced(J);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(B, false);
  std::vector<std::complex<double>> eigenvalues(solver.eigenvalues().begin(), solver.eigenvalues().end());
  // A free coordinate and its rate make a Jordan chain at zero, which rounding splits by about √ε
  // of the scale (a floating arm's ±1e-8 made it "stiff", ratio 1e8): the eigenvalues clustered at
  // zero are no rates one by one. Their sum is the trace of their block, which rounding keeps to
  // ε of the scale: a decay it still shows is the cluster's slowest rate.
  double scale = eigenvalue_scale(B, eigenvalues);
  double fastest_decay = 0, slowest = INFINITY, cluster_decay = 0;
  for (const std::complex<double>& l : eigenvalues) {
    fastest_decay = std::max(fastest_decay, -l.real());
    if (std::abs(l) > relative_cluster_tolerance * scale) slowest = std::min(slowest, std::abs(l));
    else cluster_decay -= l.real();
  }
  if (cluster_decay > relative_axis_tolerance * scale) slowest = std::min(slowest, cluster_decay);
  return std::isfinite(slowest) ? fastest_decay / slowest : 0;
}

WorkPrecision work_precision(const Problem& problem, const std::vector<double>& x0, const WorkPrecisionSettings& w,
                             const std::function<void(const std::string&)>& progress) {
  WorkPrecision out;
  SimulationSettings base;
  base.t_start = w.t_start;
  base.t_end = w.t_end;
  base.dt_out = w.dt_out;
  base.max_steps = 2'000'000;
  base.stop = w.stop;
  auto stopped = [&] { return w.stop && w.stop->load(); };
  {
    SimulationSettings s = base;
    s.integrator = "reference";
    double start = cpu_now();
    SimulationResult r = simulate(problem, x0, s);
    out.reference_seconds = cpu_now() - start;
    if (r.interrupted) {
      out.interrupted = true;
      return out;
    }
    if (r.failed) throw std::runtime_error("the reference solution failed: " + r.failure);
    out.reference = r.trajectory;
    out.reference_error_estimate = r.error_estimate;
    progress(fmt::format("reference: estimated error {:.1e}, {:.2f} s", r.error_estimate, out.reference_seconds));
  }
  out.stiffness_ratio = stiffness_ratio(problem, x0, w.t_start);
  for (const std::string& integrator : w.integrators) {
    SimulationSettings s = base;
    s.integrator = integrator;
    for (double value : fixed_step(integrator) ? w.steps : w.tolerances) {
      if (fixed_step(integrator)) s.step = value;
      else s.rtol = value, s.atol = value / 100, s.state_atol = state_absolute_tolerances(problem, x0, s.rtol, s.atol);
      WorkPrecisionRun run = measure(problem, x0, s, out.reference);
      if (stopped()) {
        out.interrupted = true;
        return out;
      }
      progress(fmt::format("{} {} {:.0e}: error {:.2e}, {:.4f} s CPU, {} rhs evaluations{}", integrator,
                           fixed_step(integrator) ? "step" : "rtol", value, run.error, run.cpu_seconds,
                           run.rhs_evaluations, run.failure.empty() ? "" : " (failed: " + run.failure + ")"));
      out.runs.push_back(run);
    }
  }
  if (!w.horizon_integrator.empty()) accuracy_horizons(problem, x0, w, out, progress);
  if (w.energy_histories)
    for (const std::string& integrator : w.integrators) {
      out.energy.push_back(energy_history(problem, x0, w, integrator));
      progress(fmt::format("energy over {:g} s, {}: final relative error {:.2e}", w.energy_horizon, integrator,
                           out.energy.back().relative_error.empty() ? NAN : out.energy.back().relative_error.back()));
    }
  return out;
}

double observed_order(const std::vector<WorkPrecisionRun>& runs, const std::string& integrator, double low, double high) {
  std::vector<const WorkPrecisionRun*> own;
  for (const WorkPrecisionRun& r : runs)
    if (r.integrator == integrator && r.step > 0 && std::isfinite(r.error)) own.push_back(&r);
  std::sort(own.begin(), own.end(), [](auto a, auto b) { return a->step > b->step; });
  // from the largest step down, while the error still falls clearly (below that, roundoff rules)
  std::vector<double> x, y;
  double previous = INFINITY;
  for (const WorkPrecisionRun* r : own) {
    if (r->error > high) continue;
    if (r->error < low || !(r->error < previous / 2)) break;
    previous = r->error;
    x.push_back(std::log10(r->step));
    y.push_back(std::log10(r->error));
  }
  if (x.size() < 2) return NAN;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / x.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

std::vector<const WorkPrecisionRun*> cheapest_at(const std::vector<WorkPrecisionRun>& runs, const std::vector<double>& levels) {
  std::vector<const WorkPrecisionRun*> best;
  for (double level : levels) {
    const WorkPrecisionRun* pick = nullptr;
    for (const WorkPrecisionRun& r : runs)
      if (std::isfinite(r.error) && r.error <= level && (!pick || r.cpu_seconds < pick->cpu_seconds)) pick = &r;
    best.push_back(pick);
  }
  return best;
}

}  // namespace eomgen::runtime
