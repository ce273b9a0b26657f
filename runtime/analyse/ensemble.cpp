#include "analyse/ensemble.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <thread>

#include <fmt/format.h>

#include "analyse/state_tolerances.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

namespace {

// SplitMix64's finalizer: a counter-based generator, so draw k needs no draws before it
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// uniform in (0, 1): 53 random bits, never 0 (log(0) in Box–Muller)
double uniform_open(unsigned long seed, long sample, int variable, int stream) {
  std::uint64_t z = mix(mix(mix(std::uint64_t(seed)) ^ std::uint64_t(sample)) ^ (std::uint64_t(variable) << 8 | std::uint64_t(stream)));
  return (double(z >> 11) + 0.5) * 0x1.0p-53;
}

double standard_normal(unsigned long seed, long sample, int variable) {
  double u1 = uniform_open(seed, sample, variable, 0), u2 = uniform_open(seed, sample, variable, 1);
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);  // Box–Muller
}

SampleRun run_sample(const EnsembleSetup& setup, long k, const std::vector<double>& times, const std::atomic<bool>& stop) {
  SampleRun run;
  Problem p = setup.base;
  std::vector<double> x0 = setup.initial_state;
  for (std::size_t v = 0; v < setup.variations.size(); ++v) {
    const Variation& var = setup.variations[v];
    double value = var.distribution.draw(setup.seed, k, int(v));
    run.drawn.push_back(value);
    std::vector<double>& target = var.target == Variation::Target::parameter ? p.parameters
                                  : var.target == Variation::Target::input   ? p.inputs
                                                                             : x0;
    target[std::size_t(var.index)] = value;
  }
  bool varies_parameters = std::any_of(setup.variations.begin(), setup.variations.end(), [](const Variation& v) {
    return v.target == Variation::Target::parameter;
  });
  if (varies_parameters && setup.initial_state_at) {
    std::optional<std::vector<double>> model_x0 = setup.initial_state_at(p.parameters);
    if (!model_x0) {
      run.failed = true;
      run.failure = "the model's initial values are not finite real numbers at this sample's parameters";
      return run;
    }
    const std::vector<bool>& given = setup.settings.given_state;
    for (std::size_t i = 0; i < x0.size(); ++i)
      if (i >= given.size() || !given[i]) x0[i] = (*model_x0)[i];
  }
  SimulationSettings settings = setup.settings;
  settings.stop = &stop;
  if (setup.state_tolerances) settings.state_atol = state_absolute_tolerances(p, x0, settings.rtol, settings.atol);
  SimulationResult r = simulate(p, x0, settings);
  run.measures.assign(setup.measures.size(), NAN);
  if (r.failed || r.trajectory.times.size() != times.size()) {
    run.failed = true;
    run.failure = r.failure.empty() ? fmt::format("the run ended at t = {:g}", r.failure_time) : r.failure;
    return run;
  }
  for (const std::string& name : setup.signals) {
    run.signals.emplace_back();
    trajectory_column(*p.model, r.trajectory, name, run.signals.back());
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < setup.measures.size(); ++i)
    if (trajectory_column(*p.model, r.trajectory, setup.measures[i].signal, values))
      run.measures[i] = measure_signal(setup.measures[i].kind, r.trajectory.times, values);
  return run;
}

}  // namespace

double Distribution::draw(unsigned long seed, long sample, int variable) const {
  switch (kind) {
    case Kind::normal: return a + b * standard_normal(seed, sample, variable);
    case Kind::uniform: return a + (b - a) * uniform_open(seed, sample, variable, 0);
    case Kind::lognormal: return std::exp(a + b * standard_normal(seed, sample, variable));
  }
  return NAN;
}

double Distribution::mean() const {
  switch (kind) {
    case Kind::normal: return a;
    case Kind::uniform: return 0.5 * (a + b);
    case Kind::lognormal: return std::exp(a + 0.5 * b * b);
  }
  return NAN;
}

std::string Distribution::text() const {
  const char* name = kind == Kind::normal ? "normal" : kind == Kind::uniform ? "uniform" : "lognormal";
  return fmt::format("{}({:g}, {:g})", name, a, b);
}

std::vector<double> ensemble_times(const SimulationSettings& s) {
  // the rule of simulate(): exact multiples of dt_out, then the final time
  std::vector<double> times{s.t_start};
  for (long k = 1;; ++k) {
    double t = s.t_start + double(k) * s.dt_out;
    bool last = t >= s.t_end * (1 - 1e-14) - 1e-300;
    times.push_back(last ? s.t_end : t);
    if (last) return times;
  }
}

EnsembleShare simulate_ensemble(const EnsembleSetup& setup, long count, PointRange range, unsigned threads,
                                const std::function<void(long, long)>& progress, const std::atomic<bool>& stop) {
  EnsembleShare share;
  share.first_sample = range.begin;
  const long end = range.last(count), size = std::max(0L, end - range.begin);
  share.samples.resize(std::size_t(size));
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<long> next{range.begin}, done{0};
  std::vector<std::thread> workers;
  share.times = ensemble_times(setup.settings);
  for (unsigned w = 0; w < threads; ++w)
    workers.emplace_back([&] {
      for (long k; (k = next++) < end && !stop; ++done)
        share.samples[std::size_t(k - range.begin)] = run_sample(setup, k, share.times, stop);
    });
  while (done < size && !stop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (progress) progress(done, size);
  }
  for (auto& t : workers) t.join();
  share.interrupted = stop && done < size;
  if (progress) progress(done, size);
  return share;
}

}  // namespace eomgen::runtime
