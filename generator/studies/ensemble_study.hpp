/// @file `eomgen ensemble`: Monte-Carlo simulation of a model over distributions of its
/// parameters, inputs and initial values, on all cores and, under mpirun, on every rank;
/// the statistics of the recorded signals over time and of scalar measures per sample.
#pragma once

#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::studies {

struct EnsembleOptions {
  std::string model;
  long samples = 100;
  unsigned long seed = 1;
  std::vector<std::string> vary, outputs, measures, sets, initials;
  std::string quantiles = "0.05,0.5,0.95";
  runtime::SimulationSettings settings;
  bool atol_given = false;  // without --atol each sample's states' sizes set their absolute tolerances
  unsigned threads = 0;
  std::string csv, plot;
  bool json = false;
};

/// The whole `eomgen ensemble` job, printed (and written to the CSV and chart asked for); its exit status.
int run_ensemble(const EnsembleOptions& options);

}  // namespace eomgen::studies
