/// @file Work against precision: every integrator at a range of tolerances (or
/// step sizes for the fixed-step methods), each run's error against a reference
/// solution and its cost, and the long-horizon energy error of each method.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

struct WorkPrecisionRun {
  std::string integrator;
  double tolerance = 0;  // rtol of the adaptive methods
  double step = 0;       // step of the fixed-step methods
  double error = 0;      // trajectory_error against the reference; NaN when the run failed
  double cpu_seconds = 0;
  long rhs_evaluations = 0, jacobian_evaluations = 0, steps = 0;
  std::string failure;
};

struct EnergyHistory {
  std::string integrator;
  std::vector<double> times, relative_error;  // |E(t) − E(0)| / |E(0)|
  std::string failure;
};

/// How long a run at one tolerance stays within 1e-2 of the run at a tenth of it.
struct AccuracyHorizon {
  double tolerance = 0, horizon = 0;  // horizon = t_end when they never part
};

struct WorkPrecisionSettings {
  double t_start = 0, t_end = 10, dt_out = 0.05;
  std::vector<std::string> integrators;
  std::vector<double> tolerances;  // rtol; atol = rtol/100
  std::vector<double> steps;       // fixed steps of rk4 and verlet
  bool energy_histories = false;   // conservative models: the long-horizon energy error
  double energy_horizon = 1000, energy_tolerance = 1e-6, energy_step = 0.01;
  std::string horizon_integrator;  // non-empty: also the accuracy horizons with this integrator
  /// When set (SIGINT, SIGTERM), the work ends after the run in hand, which is left out
  const std::atomic<bool>* stop = nullptr;
};

struct WorkPrecision {
  Trajectory reference;
  double reference_error_estimate = 0, reference_seconds = 0;
  std::vector<WorkPrecisionRun> runs;
  std::vector<EnergyHistory> energy;
  std::vector<AccuracyHorizon> horizons;
  double lyapunov_estimate = NAN;  // ln 10 over the horizon gained per decade of tolerance
  double stiffness_ratio = 0;  // see stiffness_ratio()
  bool interrupted = false;    // stopped by WorkPrecisionSettings::stop: the runs so far (none if during the reference)
};

/// The fastest decay rate (largest −Re λ) over the slowest rate (smallest nonzero |λ|) of
/// ∂x'/∂x at x0: large for stiff systems, about zero for undamped oscillations however fast.
double stiffness_ratio(const Problem& problem, const std::vector<double>& x0, double t0);
/// The same of the Jacobian J, NaN when it is not finite. Zero is relative to J's eigenvalue
/// scale (system_scales.hpp), so that the ratio does not change when J is scaled in time or
/// its states in units, and a Jordan chain at zero split by rounding is no slow rate.
double stiffness_ratio_of(const Eigen::MatrixXd& J);

/// `progress` is called with a line after every run (for the user's terminal).
WorkPrecision work_precision(const Problem& problem, const std::vector<double>& x0, const WorkPrecisionSettings& settings,
                             const std::function<void(const std::string&)>& progress);

/// The least-squares slope of log10(error) against log10(step) over the runs of one
/// fixed-step integrator, from the largest step whose error is below `high` down to
/// where the error falls below `low` or stops halving: the observed order.
double observed_order(const std::vector<WorkPrecisionRun>& runs, const std::string& integrator, double low = 1e-12,
                      double high = 1e-3);

/// For each accuracy 10^-k in `levels`: the run (any integrator) with the least CPU time
/// whose error is at most that accuracy; null entries where no run reached it.
std::vector<const WorkPrecisionRun*> cheapest_at(const std::vector<WorkPrecisionRun>& runs, const std::vector<double>& levels);

}  // namespace eomgen::runtime
