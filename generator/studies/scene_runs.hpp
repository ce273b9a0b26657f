/// @file The runs of `eomgen scene` (studies/scene_analysis.hpp): one candidate model with every
/// integrator that applies, over a range of tolerances or steps, each run's outputs measured
/// against the reference and its work counted in operations of the generated code. A run past ten
/// times the work of the cheapest one that met the accuracy so far is stopped (it cannot be chosen).
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"
#include "studies/scene_analysis.hpp"

namespace eomgen::studies {

/// Each scene output over a run, or nothing with the name the model lacks in `missing`.
std::optional<std::vector<std::vector<double>>> scene_outputs(const eomgen_model_abi& m, const runtime::Trajectory& tr,
                                                              const std::vector<std::string>& names, std::string& missing);
/// max − min of the values (0 for none)
double range_of(const std::vector<double>& v);

class SceneRuns {
 public:
  /// `a` holds the scene, the reference and the candidates; the runs are appended to a.runs.
  SceneRuns(SceneAnalysis& a, const std::function<void(const std::string&)>& progress, const std::atomic<bool>* stop)
      : a_(a), progress_(progress), stop_(stop) {}
  /// Runs candidate `index` (sets a.interrupted on a signal, the candidate's refusal if it cannot run).
  void run_candidate(std::size_t index);
  /// The outputs of run `run`, kept for the runs that met the accuracy.
  const std::vector<std::vector<double>>& outputs_of(std::size_t run) { return kept_outputs_[run]; }

 private:
  SceneAnalysis& a_;
  const std::function<void(const std::string&)>& progress_;
  const std::atomic<bool>* stop_;
  std::map<std::size_t, std::vector<std::vector<double>>> kept_outputs_;
  std::optional<std::size_t> cheapest_;  // the run of least work that met the accuracy so far
};

}  // namespace eomgen::studies
