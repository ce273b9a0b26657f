/// @file `eomgen stability` of a model whose equations depend on time: refused when
/// the dependence is not periodic, else the Floquet analysis of the equilibrium over
/// the period found from the model (or given with --period).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

struct PeriodicOptions {
  std::vector<std::string> at;
  std::string symbolic;
  double period = 0;  // given with --period; 0: found from the model
  bool json = false;
};

/// For a model whose equations depend on time: the refusal, or the Floquet analysis,
/// printed, and its exit status; nothing for an autonomous model.
std::optional<int> periodic_stability(const LoadedProblem& loaded, const PeriodicOptions& options);

}  // namespace eomgen::studies
