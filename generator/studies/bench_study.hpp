/// @file `eomgen bench`: every integrator at a range of tolerances against a reference
/// solution; writes the work-precision charts, the runs and a report with the verdict.
#pragma once

#include <string>
#include <vector>

#include "model_abi.h"

namespace eomgen::studies {

struct BenchOptions {
  std::string model, directory, integrators = "all", tolerances = "1e-3:1e-12:10";
  double t_end = 10, dt_out = 0, energy_horizon = 0, energy_tolerance = 1e-6, energy_step = 0;
  int step_count = 8;
  std::string horizon_integrator;
  std::vector<std::string> sets, initials;
};

/// The integrators that can run this model (all but the reference).
std::vector<std::string> applicable_integrators(const eomgen_model_abi& m);
/// The whole `eomgen bench` job: the runs, the charts and the report in o.directory; its exit status.
int bench(const BenchOptions& options);
/// `eomgen bench MODEL -o DIRECTORY` with the default settings.
int bench_model(const std::string& model, const std::string& directory);

}  // namespace eomgen::studies
