/// @file `eomgen linear`: the linearized system about an equilibrium or steady motion
/// (found as `stability` finds it), solved: eigenvalues with multiplicities and Jordan
/// blocks, natural frequencies and mass-normalized modes, and Φ(t) = e^{At} (Hiller §6, §8.1).
#pragma once

#include <string>
#include <vector>

#include "studies/linear_response_output.hpp"

namespace eomgen::studies {

struct LinearOptions {
  std::string model, times, outputs;
  std::vector<std::string> at, sets, transfer, bode;
  bool json = false, symbolic = false;
  ResponseOptions response;
};

/// The whole `eomgen linear` job, printed (and the charts and files asked for); its exit status.
int linear(const LinearOptions& options);

}  // namespace eomgen::studies
