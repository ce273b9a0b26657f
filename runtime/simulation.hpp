/// @file Simulating a compiled model: settings, statistics and the result,
/// plain data shared by the integrators, the reports and the command line.
#pragma once

#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "model_abi.h"

namespace eomgen::runtime {

/// The reference integrator of a compiled model: extrapolation in a wide scalar from
/// (t0, x0) to `count` output times with macro steps of at most `step`; writes the
/// states to `out`; returns the right-hand sides used, or −1 − k if output k is not finite.
using ReferenceFunction = long (*)(const double* p, const double* u, double t0, const double* x0, const double* times,
                                   std::size_t count, double step, double* out);

/// A model with its parameter and input values: x' = rhs(t, x, u, p).
struct Problem {
  const eomgen_model_abi* model = nullptr;
  std::vector<double> parameters;  // num_parameters, in parameter_names order
  std::vector<double> inputs;      // num_inputs, held constant over the run unless input_signal is set
  ReferenceFunction reference = nullptr;  // set when the model was compiled with one
  /// Inputs as functions of time: writes num_inputs values u(t), starting from `inputs`.
  std::function<void(double t, double* u)> input_signal = nullptr;
  /// u(t): `inputs`, or the signal's values written into `scratch`; nullptr without inputs.
  const double* inputs_at(double t, std::vector<double>& scratch) const;
  /// `inputs` as the generated functions take them: nullptr without inputs.
  const double* held_inputs() const { return inputs.empty() ? nullptr : inputs.data(); }
};

struct SimulationSettings {
  double t_start = 0, t_end = 10, dt_out = 0.01;
  std::string integrator = "cvode-bdf";
  double rtol = 1e-8, atol = 1e-10;
  /// num_states absolute tolerances, one per state (analyse/state_tolerances.hpp), or empty: atol
  /// for every state. Taken by the SUNDIALS integrators where the stepper's state is the model's.
  std::vector<double> state_atol;
  double step = 0;               // fixed step of rk4, verlet and gauss-legendre; 0: dt_out/10
  long max_steps = 200'000;      // between two output times
  /// > 0: the run stops (failed, `over_budget`) at the first output time after this many
  /// right-hand-side evaluations, for callers that only need runs cheaper than a known one
  long max_rhs_evaluations = 0;
  /// When set (by a signal handler: SIGINT, SIGTERM), the run ends at the next output time
  /// (failed, `interrupted`), keeping the trajectory so far
  const std::atomic<bool>* stop = nullptr;
  // constrained models: Baumgarte's stabilization (Lagrange I) and projection onto the
  // constraint manifold after every step; gains < 0 take the model's defaults. The projection
  // also keeps the quaternions of ball and free joints unit (and starts from unit ones).
  bool baumgarte = true, projection = true;
  /// num_states, or empty: the entries of x0 the user gave; constrained models keep them
  /// where the constraints allow it while making the initial state consistent
  std::vector<bool> given_state;
  double baumgarte_alpha = -1, baumgarte_beta = -1;
  /// Bounded memory whatever t_end: when set, every `stream_rows` recorded rows (and the rest at
  /// the end) go to `stream` and leave the trajectory; the summary keeps what a report needs.
  /// `stream` returns false when it cannot take them (a full disk): the run then ends (failed).
  std::function<bool(const struct Trajectory& rows)> stream = nullptr;
  std::size_t stream_rows = 4096;
  /// Called after every recorded row with its time, for a progress line on long runs.
  std::function<void(double t)> progress = nullptr;
};

/// rk4, verlet and gauss-legendre: they take the step --step, not a tolerance.
bool is_fixed_step_integrator(const std::string& name);

/// The integrators that solve Lagrange I as a differential-algebraic system.
bool is_dae_integrator(const std::string& name);

/// Why an integrator cannot run this model, or empty when it can.
std::string integrator_refusal(const eomgen_model_abi& model, const std::string& integrator);

/// The explicit integrators: on a stiff model their step is set by stability, not accuracy.
bool is_explicit_integrator(const std::string& name);

struct SolverStatistics {
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0;
  long error_test_failures = 0, convergence_failures = 0;
  double wall_seconds = 0;
};

/// One row per output time: exact multiples of dt_out and the final time.
struct Trajectory {
  std::vector<double> times;
  std::vector<std::vector<double>> states;   // num_states each
  std::vector<double> energies;              // T + V
  std::vector<std::vector<double>> outputs;  // num_outputs each
  std::vector<std::vector<double>> first_integrals;  // num_first_integrals each
  std::vector<std::vector<double>> multipliers;  // num_multipliers each (Lagrange I)
  std::vector<double> position_residuals, velocity_residuals;  // largest |g|, |C q' + b| (constrained models)
};

/// What a report needs of a whole run, kept as the rows are recorded, so that a streamed run
/// (SimulationSettings::stream) still has it.
struct RunSummary {
  std::size_t rows = 0;
  double first_time = NAN, last_time = NAN;
  std::vector<double> first_state, last_state;
  double first_energy = NAN, largest_energy_change = 0;  // max |E(t) − E(0)|; inf once E is not finite
  std::vector<double> first_integrals, largest_integral_changes;  // the same for each first integral
  std::vector<double> largest_multipliers;                         // max |λ_i| (Lagrange I)
  double largest_position_residual = 0, largest_velocity_residual = 0;
  /// The summary with row k of `trajectory` added.
  void add(const struct Trajectory& trajectory, std::size_t k);
};

struct SimulationResult {
  Trajectory trajectory;  // every row, or, when streamed, the rows not yet streamed (none at the end)
  RunSummary summary;
  double max_position_residual = 0, max_velocity_residual = 0;  // the summary's, over every row
  SolverStatistics statistics;
  bool failed = false;
  double failure_time = 0;
  int solver_flag = 0;
  std::string failure;  // what went wrong, for the user
  bool over_budget = false;  // stopped by SimulationSettings::max_rhs_evaluations
  bool interrupted = false;  // stopped by SimulationSettings::stop
  long projections = 0;
  /// Ball and free joints: the largest | |q| − 1 | over the output times (as recorded), and the
  /// largest that the projection after a step or at an output time corrected (0 when not projected)
  double largest_quaternion_norm_error = 0, largest_quaternion_correction = 0;
  std::string quaternions_normalized;  // "after every step", "at the output times", or "" (not normalized)
  std::vector<std::string> warnings;  // things the user should know although the run went on
  double error_estimate = NAN;  // the reference integrator's estimate of its own error
  double reference_step = 0;    // and its final macro step
};

/// The integrators by command-line name, the default first.
const std::vector<std::string>& integrator_names();

/// Integrates from x0 over [t_start, t_end], recording at the output times.
/// A failure ends the run with `failed` set; the rows before it are kept.
SimulationResult simulate(const Problem& problem, const std::vector<double>& x0, const SimulationSettings& settings);

}  // namespace eomgen::runtime
