/// @file The reduced candidates of `eomgen scene` (issue: model no more than a scene needs):
/// the model without the coordinates the scene's outputs do not need (frozen where their motion
/// stays negligible, dropped where they do not feed back), and the linear model truncated to the
/// modes the scene excites.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

struct ReducedCandidate {
  std::optional<Equations> equations;  // empty: nothing to reduce, `description` says why
  std::string description;
  /// the largest |x| along the reference of each state the full model lacks (a modal model's η and
  /// der(η)), by name, for the runs' absolute tolerances
  std::map<std::string, double> state_sizes = {};
};

/// `model_path`, `scene`: as for derive_model_file_for. The coordinates that do not feed back
/// into the scene's outputs are dropped (derive/decoupled_coordinates.hpp); of the rest, those the
/// outputs do not name whose range along the reference (`ranges`, per coordinate) stays below the
/// accuracy times the largest range are held at their initial values.
ReducedCandidate reduced_candidate(const std::string& model_path, const Scene& scene,
                                   const std::vector<std::pair<std::string, double>>& ranges);

/// What the modal candidate needs of the scene's reference run of the full model.
struct SceneMotion {
  std::vector<std::vector<double>> states;   // x(t) of the reference
  std::vector<std::vector<double>> outputs;  // per scene output, per time
  double accuracy = 0;
};

/// `linear`: the linear model about `equilibrium` (x = [q0; 0]) of the loaded full model.
/// Refused (with the reason) for gyroscopic, circulatory or nonproportionally damped systems,
/// and when every mode is needed.
ReducedCandidate modal_candidate(const LoadedProblem& full, const Equations& linear, const std::vector<double>& equilibrium,
                                 const Scene& scene, const SceneMotion& motion);

}  // namespace eomgen::studies
