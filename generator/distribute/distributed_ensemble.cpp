#include "distribute/distributed_ensemble.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace eomgen::distribute {

namespace {

// one signal of every sample of the share, sample after sample; NaN rows for failed runs
std::vector<double> pack_signal(const runtime::EnsembleShare& share, std::size_t signal) {
  std::vector<double> out;
  out.reserve(share.samples.size() * share.times.size());
  for (const runtime::SampleRun& run : share.samples) {
    if (run.failed || run.signals.empty()) out.insert(out.end(), share.times.size(), NAN);
    else out.insert(out.end(), run.signals[signal].begin(), run.signals[signal].end());
  }
  return out;
}

runtime::SignalBands bands_of(const std::string& signal, const std::vector<double>& all, std::size_t times,
                              const std::vector<double>& probabilities) {
  runtime::SignalBands bands{signal, {}};
  std::size_t samples = times ? all.size() / times : 0;
  std::vector<double> column(samples);
  for (std::size_t k = 0; k < times; ++k) {
    for (std::size_t j = 0; j < samples; ++j) column[j] = all[j * times + k];
    bands.at_time.push_back(runtime::sample_statistics(column, probabilities));
  }
  return bands;
}

}  // namespace

EnsembleResult distributed_ensemble(const Ranks& ranks, const runtime::EnsembleSetup& setup, long samples,
                                    const std::vector<double>& probabilities, unsigned threads,
                                    const std::function<void(long, long)>& progress, const std::atomic<bool>& stop) {
  auto started = std::chrono::steady_clock::now();
  Block block = ranks.share(samples);
  runtime::EnsembleShare share =
      runtime::simulate_ensemble(setup, samples, runtime::PointRange{block.begin, block.end}, threads, progress, stop);
  EnsembleResult result;
  result.times = share.times;
  result.samples = samples;
  result.interrupted = ranks.any(share.interrupted);
  if (result.interrupted) return result;

  for (std::size_t s = 0; s < setup.signals.size(); ++s) {
    std::vector<double> all = ranks.gather(pack_signal(share, s));
    if (ranks.is_root()) result.bands.push_back(bands_of(setup.signals[s], all, share.times.size(), probabilities));
  }
  std::vector<double> measures, failed, first, drawn;
  std::string why;
  for (std::size_t k = 0; k < share.samples.size(); ++k) {
    const runtime::SampleRun& run = share.samples[k];
    measures.insert(measures.end(), run.measures.begin(), run.measures.end());
    std::vector<double> draws = run.drawn;
    draws.resize(setup.variations.size(), NAN);
    drawn.insert(drawn.end(), draws.begin(), draws.end());
    failed.push_back(run.failed ? 1.0 : 0.0);
    if (run.failed && first.empty()) {
      first.push_back(double(block.begin + long(k)));
      first.insert(first.end(), run.drawn.begin(), run.drawn.end());
      why = run.failure;
    }
  }
  std::vector<double> all_measures = ranks.gather(measures), all_failed = ranks.gather(failed),
                      all_first = ranks.gather(first), all_drawn = ranks.gather(drawn);
  std::vector<std::string> reasons = ranks.gather_text(why);
  if (ranks.is_root()) {
    std::size_t count = setup.measures.size();
    std::size_t variables = setup.variations.size();
    std::vector<std::vector<double>> draws;
    for (std::size_t k = 0; k < all_failed.size(); ++k)
      draws.emplace_back(all_drawn.begin() + long(k * variables), all_drawn.begin() + long((k + 1) * variables));
    for (std::size_t m = 0; m < count; ++m) {
      std::vector<double> values;
      for (std::size_t j = m; j < all_measures.size(); j += count) values.push_back(all_measures[j]);
      result.measures.push_back(runtime::sample_statistics(values, probabilities));
      // a finished run whose measure is NaN was left out of the statistics: how many, and
      // whether the loss follows a drawn value (then the statistics of the rest are biased)
      std::vector<std::vector<double>> finished_draws;
      std::vector<bool> left_out;
      for (std::size_t k = 0; k < values.size() && k < all_failed.size(); ++k) {
        if (all_failed[k] != 0) continue;
        finished_draws.push_back(draws[k]);
        left_out.push_back(!std::isfinite(values[k]));
      }
      result.measures_left_out.push_back(long(std::count(left_out.begin(), left_out.end(), true)));
      result.measures_bias.push_back(runtime::selection_dependence(finished_draws, left_out));
    }
    for (double f : all_failed) result.failed += f != 0;
    // the ranks hold samples in order, so the first rank with a failure has the lowest
    if (!all_first.empty()) {
      result.first_failed = long(all_first[0]);
      result.first_failed_drawn.assign(all_first.begin() + 1, all_first.begin() + 1 + long(setup.variations.size()));
      for (const std::string& r : reasons)
        if (!r.empty()) {
          result.first_failure = r;
          break;
        }
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace eomgen::distribute
