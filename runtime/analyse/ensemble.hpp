/// @file Monte-Carlo ensembles: the same model simulated from parameters, inputs and initial
/// values drawn from distributions. Sample k's draws depend only on the seed, k and the
/// variable, so a sample is the same whichever process or thread simulates it, and the
/// statistics do not depend on how the samples were split.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analyse/sample_statistics.hpp"
#include "analyse/signal_measures.hpp"
#include "analyse/stability_map.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

struct Distribution {
  enum class Kind { normal, uniform, lognormal } kind = Kind::normal;
  double a = 0, b = 1;  // normal(mean, sd), uniform(low, high), lognormal(mu, sigma) of log x
  /// The draw of sample `sample` for variable `variable` under `seed`.
  double draw(unsigned long seed, long sample, int variable) const;
  double mean() const;
  std::string text() const;  // "normal(1, 0.05)"
};

/// What a variation draws: a parameter, an input (held over the run) or an entry of the
/// initial state.
struct Variation {
  enum class Target { parameter, input, state } target = Target::parameter;
  int index = 0;
  std::string name;
  Distribution distribution;
};

struct EnsembleSetup {
  Problem base;
  std::vector<double> initial_state;
  /// The model's initial values at a sample's parameters, when they are expressions in them
  /// (r = "l0 + m*g/k"): called for each sample that varies a parameter, from several threads;
  /// empty when initial_state serves every sample. The entries of settings.given_state (given
  /// with --initial, or drawn) keep their values.
  std::function<std::optional<std::vector<double>>(const std::vector<double>& parameters)> initial_state_at;
  SimulationSettings settings;
  /// each sample's absolute tolerances from its own states' sizes (analyse/state_tolerances.hpp),
  /// settings.atol the largest: where no --atol was given
  bool state_tolerances = false;
  std::vector<Variation> variations;
  std::vector<std::string> signals;  // recorded over time: coordinates, velocities, outputs, energy
  std::vector<Measure> measures;     // one number per sample each
  unsigned long seed = 1;
};

struct SampleRun {
  bool failed = false;
  std::string failure;                        // why, when failed
  std::vector<double> drawn;                  // one per variation
  std::vector<std::vector<double>> signals;   // per signal, its values at `times` (empty when failed)
  std::vector<double> measures;               // per measure (NaN when failed or undefined)
};

struct EnsembleShare {
  long first_sample = 0;
  std::vector<double> times;  // the output times every sample is recorded at
  std::vector<SampleRun> samples;
  bool interrupted = false;
};

/// A recorded signal's statistics over the samples at each output time.
struct SignalBands {
  std::string signal;
  std::vector<SampleStatistics> at_time;
};

/// The output times of a run with these settings (multiples of dt_out and the end).
std::vector<double> ensemble_times(const SimulationSettings& settings);

/// Simulates samples [range.begin, range.end) of `count` on `threads` threads (0: all
/// cores); `progress(done, share)` is called from the calling thread; `stop` ends it early.
EnsembleShare simulate_ensemble(const EnsembleSetup& setup, long count, PointRange range, unsigned threads,
                                const std::function<void(long, long)>& progress, const std::atomic<bool>& stop);

}  // namespace eomgen::runtime
