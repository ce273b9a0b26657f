#include "studies/scene_runs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analyse/state_tolerances.hpp"

namespace eomgen::studies {

// each scene output over the run, or the name the model lacks
std::optional<std::vector<std::vector<double>>> scene_outputs(const eomgen_model_abi& m, const runtime::Trajectory& tr,
                                                              const std::vector<std::string>& names, std::string& missing) {
  std::vector<std::vector<double>> out;
  for (const std::string& name : names) {
    int state = state_index(m, name), output = index_of(m.output_names, m.num_outputs, name);
    if (state < 0 && output < 0) {
      missing = name;
      return std::nullopt;
    }
    std::vector<double> column;
    for (std::size_t k = 0; k < tr.times.size(); ++k)
      column.push_back(state >= 0 ? tr.states[k][std::size_t(state)] : tr.outputs[k][std::size_t(output)]);
    out.push_back(column);
  }
  return out;
}

double range_of(const std::vector<double>& v) {
  auto [low, high] = std::minmax_element(v.begin(), v.end());
  return v.empty() ? 0 : *high - *low;
}

namespace {

constexpr double work_budget_factor = 10;

// the error of a run relative to each output's range, and whether (and where) it broke the accuracy
void measure(const SceneAnalysis& a, const std::vector<double>& times, const std::vector<std::vector<double>>& y, SceneRun& run) {
  run.error = 0, run.meets_accuracy = times.size() == a.times.size();
  for (std::size_t k = 0; k < y.size(); ++k) {
    const std::vector<double>& reference = a.reference_outputs[k];
    double range = std::max(range_of(reference), 1e-300), bound = a.scene.accuracy * range + a.scene.absolute;
    for (std::size_t i = 0; i < std::min(times.size(), reference.size()); ++i) {
      double d = std::abs(y[k][i] - reference[i]);
      if (!std::isfinite(d)) d = INFINITY;
      run.error = std::max(run.error, d / range);
      if (d > bound && (std::isnan(run.broke_at) || times[i] < run.broke_at)) run.broke_at = times[i], run.meets_accuracy = false;
    }
  }
}

// Each state's absolute tolerance at `rtol`: rtol/100 of its largest |x| along the reference (by
// name; for a state the full model does not have, a modal coordinate, its size in the candidate's
// own start), rtol/100 where nothing gives it a size. The same swing at any amplitude then gets
// the same choice. One rtol/100 in every unit had made a swing of 5e-10 rad need rtol 1e-9 where
// one of 0.05 rad took 1e-5 with the same model, and twice the work; a cap of one unit (as
// `simulate` keeps for its default) changed the choice between amplitudes of 1e-6 and 1.
std::vector<double> scene_state_tolerances(const SceneAnalysis& a, const runtime::Problem& problem, const eomgen_model_abi& m,
                                           const std::vector<double>& x0, double rtol) {
  std::vector<double> own = runtime::state_sizes(problem, x0), atol;
  for (std::size_t i = 0; i < m.num_states; ++i) {
    auto in_reference = a.reference_state_sizes.find(m.state_names[i]);
    double size = in_reference != a.reference_state_sizes.end() ? in_reference->second : own[i];
    atol.push_back(rtol / 100 * (size > 0 ? size : 1.0));
  }
  return atol;
}

std::vector<std::pair<std::string, double>> run_settings(const std::string& integrator, double dt_out) {
  std::vector<std::pair<std::string, double>> out;
  if (runtime::is_fixed_step_integrator(integrator)) {
    for (double divide : {1.0, 4.0, 16.0}) out.push_back({"step", dt_out / divide});
  } else {
    for (double tolerance : {1e-3, 1e-5, 1e-7, 1e-9}) out.push_back({"rtol", tolerance});
  }
  return out;
}

}  // namespace

void SceneRuns::run_candidate(std::size_t index) {
  SceneCandidate& c = a_.candidates[index];
  if (!c.refusal.empty()) return;
  LoadedProblem loaded;
  if (load_equations(c.equations, {}, loaded)) {
    c.refusal = "its header does not load";
    return;
  }
  const eomgen_model_abi& m = *loaded.compiled->abi();
  progress_(fmt::format("scene {}: candidate {} ({} operations in rhs)", a_.scene.name, c.model, c.rhs_operations));
  for (const std::string& integrator : runtime::integrator_names()) {
    if (integrator == "reference" || !runtime::integrator_refusal(m, integrator).empty()) continue;
    for (const auto& [kind, value] : run_settings(integrator, a_.scene.dt_out)) {
      runtime::SimulationSettings s;
      s.t_end = a_.scene.t_end, s.dt_out = a_.scene.dt_out, s.integrator = integrator, s.stop = stop_;
      if (kind == "step") s.step = value;
      else s.rtol = value, s.atol = value / 100, s.state_atol = scene_state_tolerances(a_, loaded.problem, m, loaded.initial_state, value);
      // a run past the work of the cheapest accepted one cannot be chosen; it runs on to ten
      // times that work so the report can still show each candidate's best, then stops
      if (cheapest_ && c.rhs_operations > 0)
        s.max_rhs_evaluations = long(work_budget_factor * a_.runs[*cheapest_].work / double(c.rhs_operations)) + 1;
      SceneRun run;
      run.candidate = index, run.integrator = integrator, run.setting = fmt::format("{} {:g}", kind, value);
      runtime::SimulationResult r;
      try {
        r = runtime::simulate(loaded.problem, loaded.initial_state, s);
      } catch (const std::exception& why) {
        r.failed = true, r.failure = why.what();
      }
      if (r.interrupted) {
        a_.interrupted = true;
        return;
      }
      run.cpu_seconds = r.statistics.wall_seconds;
      run.rhs_evaluations = r.statistics.rhs_evaluations, run.jacobian_evaluations = r.statistics.jacobian_evaluations;
      run.work = double(run.rhs_evaluations) * double(c.rhs_operations) +
                 double(run.jacobian_evaluations) * double(c.jacobian_operations);
      std::string missing;
      auto y = scene_outputs(m, r.trajectory, a_.scene.outputs, missing);
      if (!y) {
        c.refusal = "it has no " + missing + ", which the scene asks for";
        return;
      }
      measure(a_, r.trajectory.times, *y, run);
      if (r.over_budget) {
        const SceneRun& cheaper = a_.runs[*cheapest_];
        run.stopped = true, run.meets_accuracy = false, run.error = run.broke_at = NAN;
        run.rejected_because = fmt::format("stopped at t = {:g}: more than {:g} times the work the {} model with {} ({}) needs",
                                           r.failure_time, work_budget_factor, a_.candidates[cheaper.candidate].model, cheaper.integrator,
                                           cheaper.setting);
      } else if (r.failed) run.meets_accuracy = false, run.rejected_because = "the run failed: " + r.failure;
      else if (!run.meets_accuracy)
        run.rejected_because = fmt::format("error {:.2g} of the range > accuracy {:g}, first at t = {:g}", run.error,
                                           a_.scene.accuracy, run.broke_at);
      if (run.meets_accuracy) {
        kept_outputs_[a_.runs.size()] = *y;
        if (!cheapest_ || run.work < a_.runs[*cheapest_].work) cheapest_ = a_.runs.size();
      }
      a_.runs.push_back(run);
    }
  }
}

}  // namespace eomgen::studies
