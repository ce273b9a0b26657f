/// @file `eomgen sweep`: the eigenvalues along one parameter with the crossings of the
/// imaginary axis, or a stability map over two parameters, on all cores, with the
/// symbolic boundary over it when asked.
#pragma once

#include <string>
#include <vector>

namespace eomgen::studies {

struct SweepOptions {
  std::string model;
  std::vector<std::string> params, at, sets;
  std::string csv, plot;
  bool symbolic = false, json = false;
  unsigned threads = 0;
};

/// The whole `eomgen sweep` job, printed (and written to the CSV and chart asked for); its exit status.
int run_sweep(const SweepOptions& options);

}  // namespace eomgen::studies
