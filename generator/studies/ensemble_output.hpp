/// @file What `eomgen ensemble` writes and prints: the statistics of the recorded signals
/// over time (CSV), and the summary with the statistics of the measures (text or JSON).
#pragma once

#include <string>
#include <vector>

#include "analyse/ensemble.hpp"
#include "distribute/distributed_ensemble.hpp"
#include "distribute/ranks.hpp"

namespace eomgen::studies {

/// t, then for each signal its mean, standard deviation and quantiles: SIGNAL.mean,
/// SIGNAL.sd, SIGNAL.q0.05, ...; an empty field where no sample has a value.
std::string ensemble_csv(const distribute::EnsembleResult& result, const std::vector<double>& probabilities);

struct EnsembleDescription {
  std::string model, integrator;
  const runtime::EnsembleSetup* setup = nullptr;
  std::vector<double> probabilities;
  std::string ranks;  // "2 ranks"
  int rank_count = 1;
};

void print_ensemble_text(const distribute::EnsembleResult& result, const EnsembleDescription& d);
void print_ensemble_json(const distribute::EnsembleResult& result, const EnsembleDescription& d);

}  // namespace eomgen::studies
