/// @file `eomgen scene`: the cheapest model and integrator that answer a scene's question
/// to its accuracy (Hiller §1.1). Candidates from cheap to full (the linearization about
/// the equilibrium nearest the start, and it in the modes the scene excites; the full model
/// without negligible terms; without the coordinates the outputs do not need; the declared
/// variants; the full model), each run with every applicable integrator over a
/// range of tolerances, its error on the scene's outputs measured against the full
/// model's reference and its work counted in operations of the generated code.
#pragma once

#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen::studies {

struct SceneRun {
  std::size_t candidate = 0;
  std::string integrator, setting;  // "rtol 1e-06" or "step 0.01"
  double error = NAN;               // max over outputs and times of |y − y_ref| / range(y_ref)
  double broke_at = NAN;            // the first time the accuracy was broken
  double cpu_seconds = 0;
  long rhs_evaluations = 0, jacobian_evaluations = 0;
  double work = 0;                  // rhs evaluations · rhs operations + Jacobians · Jacobian operations
  bool meets_accuracy = false;
  bool stopped = false;  // stopped at ten times the work of a run that met the accuracy already
  std::string rejected_because;
};

struct SceneCandidate {
  std::string model;        // "full", "linear", "reduced:modal", "pruned", "reduced", "variant:NAME"
  std::string description;  // what was simplified
  std::string refusal;      // why it was not run, or empty
  Equations equations;
  std::string header;
  long rhs_operations = 0, jacobian_operations = 0;
};

struct SceneAnalysis {
  std::string refusal;  // the scene cannot be analysed at all (printed already), or empty
  Scene scene;
  std::string model_name, reference_integrator;
  double reference_error_estimate = NAN;
  std::vector<double> times;
  std::vector<std::vector<double>> reference_outputs;  // per output, per time
  /// each state's largest |x| along the reference, by name: the candidates' absolute tolerances
  std::map<std::string, double> reference_state_sizes;
  std::vector<SceneCandidate> candidates;
  std::vector<SceneRun> runs;
  std::optional<std::size_t> chosen, closest;  // indices into runs
  std::vector<std::vector<double>> chosen_outputs;  // per output, per time
  std::string noise_note;  // when the choice is within measurement noise of another model's run
  bool interrupted = false;  // stopped by a signal: the choice is among the runs so far
};

/// `progress` gets one line per candidate. When `stop` is set (SIGINT, SIGTERM), the run in hand
/// is left out and no further one starts.
SceneAnalysis analyse_scene(const std::string& model_path, const std::string& scene,
                            const std::function<void(const std::string&)>& progress, const std::atomic<bool>* stop = nullptr);

}  // namespace eomgen::studies
