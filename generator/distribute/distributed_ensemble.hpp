/// @file A Monte-Carlo ensemble split over the ranks of a run: each rank simulates its
/// block of samples; rank 0 gathers them in sample order and forms the statistics, so they
/// are the same bits on any number of ranks.
#pragma once

#include "analyse/ensemble.hpp"
#include "distribute/ranks.hpp"

namespace eomgen::distribute {

struct EnsembleResult {
  std::vector<double> times;
  long samples = 0, failed = 0;
  bool interrupted = false;
  std::vector<runtime::SignalBands> bands;         // per recorded signal
  std::vector<runtime::SampleStatistics> measures;  // per measure, over the samples
  std::vector<long> measures_left_out;              // per measure, finished samples it is undefined for
  std::vector<runtime::SelectionDependence> measures_bias;  // per measure: does the loss follow a drawn value?
  long first_failed = -1;                           // the lowest failed sample, −1 when none
  std::vector<double> first_failed_drawn;           // its draws
  std::string first_failure;                        // and why it failed
  double seconds = 0;
};

/// The statistics on rank 0 (quantiles at `probabilities`); on the other ranks only the counts.
EnsembleResult distributed_ensemble(const Ranks& ranks, const runtime::EnsembleSetup& setup, long samples,
                                    const std::vector<double>& probabilities, unsigned threads,
                                    const std::function<void(long, long)>& progress, const std::atomic<bool>& stop);

}  // namespace eomgen::distribute
