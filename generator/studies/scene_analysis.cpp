#include "studies/scene_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "analyse/equilibrium.hpp"
#include "analyse/state_tolerances.hpp"
#include "symbolic_analysis/term_pruning.hpp"
#include "analyse/work_precision.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/scene_candidates.hpp"
#include "studies/scene_runs.hpp"
#include "derive/linear_model.hpp"
#include "emit/cpp_header.hpp"
#include "emit/operation_count.hpp"

namespace eomgen::studies {

namespace {


class SceneAnalyser {
 public:
  SceneAnalyser(const std::string& path, const std::string& scene, const std::function<void(const std::string&)>& progress,
                const std::atomic<bool>* stop)
      : path_(path), scene_(scene), progress_(progress), stop_(stop) {}

  SceneAnalysis run() {
    Derivation full = derive_model_file_for(path_, {scene_, "", {}});
    if (!full.diagnostics.empty()) return refused(full.diagnostics.format());
    for (const Scene& s : full.equations->scenes)
      if (s.name == scene_) a_.scene = s;
    a_.model_name = full.equations->model_name;
    LoadedProblem loaded;
    if (load_equations(*full.equations, {}, loaded)) return refused("the full model does not load");
    if (!reference(loaded)) return a_;
    std::optional<Equations> linear = linear_model(loaded);
    add_candidate("linear", "linearized about the equilibrium nearest the start", linear);
    if (linear) {
      ReducedCandidate modal = modal_candidate(loaded, *linear, equilibrium_, a_.scene, {reference_states_, a_.reference_outputs, a_.scene.accuracy});
      add_candidate("reduced:modal", modal.description, modal.equations);
      a_.reference_state_sizes.insert(modal.state_sizes.begin(), modal.state_sizes.end());
    }
    add_pruned(loaded);
    ReducedCandidate reduced = reduced_candidate(path_, a_.scene, coordinate_ranges(loaded));
    add_candidate("reduced", reduced.description, reduced.equations);
    for (const Variant& v : full.equations->variants_declared) {
      Derivation d = derive_model_file_for(path_, {scene_, v.name, {}});
      add_candidate("variant:" + v.name, "the declared variant " + v.name,
                    d.diagnostics.empty() ? std::optional<Equations>(*d.equations) : std::nullopt, d.diagnostics.format());
    }
    add_candidate("full", "the model as written", *full.equations);
    SceneRuns runs(a_, progress_, stop_);
    for (std::size_t c = 0; c < a_.candidates.size() && !a_.interrupted; ++c) runs.run_candidate(c);
    choose(runs);
    return a_;
  }

 private:
  SceneAnalysis refused(const std::string& why) {
    a_.refusal = why;
    return a_;
  }

  // the full model at its tightest: the reference integrator where it applies
  bool reference(LoadedProblem& loaded) {
    runtime::SimulationSettings s;
    s.t_end = a_.scene.t_end, s.dt_out = a_.scene.dt_out;
    // the reference integrator is explicit: on a stiff model stability, not accuracy, would set its step
    double stiffness = runtime::stiffness_ratio(loaded.problem, loaded.initial_state, 0);
    bool extrapolation = loaded.problem.reference && !(stiffness > 1e3);
    s.integrator = extrapolation ? "reference" : "cvode-bdf";
    s.rtol = 1e-12, s.atol = 1e-14;
    s.state_atol = runtime::state_absolute_tolerances(loaded.problem, loaded.initial_state, s.rtol, s.atol);
    s.stop = stop_;
    a_.reference_integrator = extrapolation ? "reference"
                              : loaded.problem.reference
                                  ? fmt::format("cvode-bdf at rtol 1e-12 (the model is stiff, ratio {:.2g})", stiffness)
                                  : "cvode-bdf at rtol 1e-12";
    progress_(fmt::format("scene {}: reference of the full model with {}", a_.scene.name, a_.reference_integrator));
    runtime::SimulationResult r = runtime::simulate(loaded.problem, loaded.initial_state, s);
    if (r.interrupted) {
      a_.interrupted = true;
      return false;
    }
    if (r.failed) {
      a_.refusal = "the reference run failed: " + r.failure;
      return false;
    }
    a_.reference_error_estimate = r.error_estimate;
    a_.times = r.trajectory.times;
    std::string missing;
    auto y = scene_outputs(*loaded.compiled->abi(), r.trajectory, a_.scene.outputs, missing);
    a_.reference_outputs = *y;
    reference_states_ = r.trajectory.states;
    const eomgen_model_abi& m = *loaded.compiled->abi();
    for (std::size_t i = 0; i < m.num_states; ++i) {
      double largest = 0;
      for (const std::vector<double>& x : reference_states_) largest = std::max(largest, std::abs(x[i]));
      a_.reference_state_sizes[m.state_names[i]] = largest;
    }
    return true;
  }

  std::optional<Equations> linear_model(LoadedProblem& loaded) {
    runtime::Equilibrium eq = runtime::find_equilibrium(loaded.problem, loaded.initial_state);
    if (!eq.converged) {
      linear_refusal_ = "no equilibrium was found near the start";
      return std::nullopt;
    }
    std::string refusal;
    equilibrium_ = eq.state;
    Equations linear = linearized_model(loaded.equations, eq.state, refusal);
    if (!refusal.empty()) {
      linear_refusal_ = refusal;
      return std::nullopt;
    }
    return linear;
  }

  // the terms of M and f below a tenth of the accuracy along the reference, dropped
  void add_pruned(const LoadedProblem& loaded) {
    Pruning p = prune_terms(loaded.equations, loaded.problem.parameters, loaded.problem.inputs, a_.times, reference_states_,
                            0.1 * a_.scene.accuracy);
    std::string dropped;
    for (std::size_t i = 0; i < p.dropped.size(); ++i)
      dropped += i < 4 ? (i ? ", " : "") + p.dropped[i] : i == 4 ? fmt::format(" and {} more", p.dropped.size() - 4) : "";
    add_candidate("pruned", p.refusal.empty() ? "dropped " + dropped : p.refusal,
                  p.refusal.empty() ? std::optional<Equations>(p.equations) : std::nullopt);
  }

  // each coordinate's range of motion along the reference
  std::vector<std::pair<std::string, double>> coordinate_ranges(const LoadedProblem& loaded) const {
    const Symbols& s = loaded.equations.symbols;
    std::vector<std::pair<std::string, double>> out;
    for (std::size_t i = 0; i < s.num_coordinates(); ++i) {
      std::vector<double> q;
      for (const auto& x : reference_states_) q.push_back(x[i]);
      out.push_back({s.coordinate_names[i], range_of(q)});
    }
    return out;
  }

  void add_candidate(const std::string& name, const std::string& description, std::optional<Equations> e,
                     const std::string& why = "") {
    SceneCandidate c;
    c.model = name, c.description = description;
    if (!e) {
      c.refusal = name == "linear" ? linear_refusal_ : !why.empty() ? why : description;
    } else {
      c.equations = *e;
      c.header = emit_cpp_header(c.equations);
      c.rhs_operations = count_operations(c.header, "rhs", c.equations.num_velocities());
      c.jacobian_operations = count_operations(c.header, "jacobian_state", c.equations.num_velocities());
    }
    a_.candidates.push_back(c);
  }

  void choose(SceneRuns& runs) {
    for (std::size_t i = 0; i < a_.runs.size(); ++i) {
      const SceneRun& r = a_.runs[i];
      if (!r.stopped && (!a_.closest || r.error < a_.runs[*a_.closest].error)) a_.closest = i;
      if (!r.meets_accuracy) continue;
      if (!a_.chosen || r.work < a_.runs[*a_.chosen].work) a_.chosen = i;
    }
    if (!a_.chosen) return;
    const SceneRun& best = a_.runs[*a_.chosen];
    a_.chosen_outputs = runs.outputs_of(*a_.chosen);
    // the work count decides; say so when another model's run is within 10 % of it
    for (const SceneRun& r : a_.runs)
      if (r.meets_accuracy && r.candidate != best.candidate && r.work <= 1.1 * best.work)
        a_.noise_note = fmt::format("the {} model with {} ({}) needs within 10 % of the same work", a_.candidates[r.candidate].model,
                                    r.integrator, r.setting);
    for (SceneRun& r : a_.runs)
      if (r.meets_accuracy && &r != &a_.runs[*a_.chosen])
        r.rejected_because = fmt::format("meets the accuracy, but needs {:.3g} times the work", r.work / std::max(best.work, 1.0));
  }

  const std::string &path_, &scene_;
  const std::function<void(const std::string&)>& progress_;
  const std::atomic<bool>* stop_;
  SceneAnalysis a_;
  std::vector<std::vector<double>> reference_states_;
  std::vector<double> equilibrium_;
  std::string linear_refusal_;
};

}  // namespace

SceneAnalysis analyse_scene(const std::string& model_path, const std::string& scene,
                            const std::function<void(const std::string&)>& progress, const std::atomic<bool>* stop) {
  return SceneAnalyser(model_path, scene, progress, stop).run();
}

}  // namespace eomgen::studies
