/// @file The pruned candidate of a scene: the terms of M and f whose size along the scene's
/// reference trajectory stays below a share of the accuracy, dropped. Each entry is expanded
/// into its terms, each term measured at samples of the trajectory against the largest
/// value of its entry (of the diagonal of M for M), and the small ones removed; what is
/// left is still a sum of the model's own terms, readable as before.
#pragma once

#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct Pruning {
  Equations equations;               // named <model>_pruned
  std::vector<std::string> dropped;  // "f[0]: -d*der(phi)", one per term
  std::string refusal;               // why nothing was pruned, or empty
};

/// `states`: the reference trajectory's rows (coordinates, then velocities) at `times`;
/// a term is dropped when its largest magnitude is at most `share` times that of its entry.
Pruning prune_terms(const Equations& equations, const std::vector<double>& parameters, const std::vector<double>& inputs,
                    const std::vector<double>& times, const std::vector<std::vector<double>>& states, double share);

}  // namespace eomgen
