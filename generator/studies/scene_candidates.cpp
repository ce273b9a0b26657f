#include "studies/scene_candidates.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analyse/excited_modes.hpp"
#include "analyse/modal_analysis.hpp"
#include "analyse/state_space.hpp"
#include "derive/decoupled_coordinates.hpp"
#include "derive/modal_model.hpp"
#include "studies/scene_runs.hpp"

namespace eomgen::studies {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// coordinates the outputs do not name whose range of motion stays below the accuracy times the
// largest range of the coordinates kept (one coordinate at least stays)
std::vector<std::string> negligible_coordinates(const Scene& scene, const std::vector<std::pair<std::string, double>>& ranges,
                                                const std::vector<std::string>& dropped) {
  auto is_dropped = [&](const std::string& q) { return std::find(dropped.begin(), dropped.end(), q) != dropped.end(); };
  double largest = 0;
  std::size_t kept = 0;
  for (const auto& [q, range] : ranges)
    if (!is_dropped(q)) largest = std::max(largest, range), ++kept;
  std::vector<std::string> out;
  for (const auto& [q, range] : ranges) {
    bool named = std::any_of(scene.outputs.begin(), scene.outputs.end(),
                             [&, &q = q](const std::string& y) { return y == q || y == "der(" + q + ")"; });
    if (!named && !is_dropped(q) && range <= scene.accuracy * largest && out.size() + 1 < kept) out.push_back(q);
  }
  return out;
}

}  // namespace

ReducedCandidate reduced_candidate(const std::string& model_path, const Scene& scene,
                                   const std::vector<std::pair<std::string, double>>& ranges) {
  // dropping is exact and freezing is not: what does not feed back is dropped first
  Derivation whole = derive_model_file_for(model_path, {scene.name, "", {}});
  if (!whole.diagnostics.empty()) return {std::nullopt, "the model does not derive for the scene"};
  std::vector<std::string> dropped = drop_coordinates_not_fed_back(*whole.equations, scene.outputs);
  std::vector<std::string> frozen = negligible_coordinates(scene, ranges, dropped);
  if (frozen.empty() && dropped.empty())
    return {std::nullopt, "no coordinate stays negligible, and every one feeds back into the outputs"};
  if (!frozen.empty()) {
    Derivation d = derive_model_file_for(model_path, {scene.name, "", frozen});
    if (!d.diagnostics.empty()) return {std::nullopt, "the model with " + joined(frozen) + " frozen does not derive"};
    dropped = drop_coordinates_not_fed_back(*d.equations, scene.outputs);
    whole.equations = d.equations;
  }
  whole.equations->model_name += "_reduced";
  std::string description;
  if (!frozen.empty()) description = "frozen at their initial values: " + joined(frozen);
  if (!dropped.empty())
    description += (description.empty() ? "" : "; ") + std::string("dropped, as they do not feed back into the outputs: ") + joined(dropped);
  return {*whole.equations, description};
}

ReducedCandidate modal_candidate(const LoadedProblem& full, const Equations& linear, const std::vector<double>& equilibrium,
                                 const Scene& scene, const SceneMotion& motion) {
  runtime::StabilityReport report = runtime::analyse_stability(full.problem, equilibrium);
  if (std::string why = runtime::symmetric_problem_refusal(report); !why.empty()) return {std::nullopt, why};
  runtime::ModalAnalysis modes = runtime::modal_analysis(report.M, report.D, report.K);
  if (!modes.refusal.empty()) return {std::nullopt, modes.refusal};
  // a damping coupling the modes is kept between the modes kept (the projection keeps it); between a mode
  // kept and one left out it is lost, which the runs measure: only a coupling near the accuracy refuses
  if (modes.damping == "nonproportional" && modes.coupling > 0.1 * motion.accuracy)
    return {std::nullopt, fmt::format("the damping couples the modes (not proportional, coupling {:.2g})", modes.coupling)};
  Eigen::MatrixXd C, D;
  runtime::output_matrices(full.problem, equilibrium, scene.outputs, C, D);
  std::vector<double> ranges;
  for (const std::vector<double>& y : motion.outputs) ranges.push_back(range_of(y));
  std::size_t n = std::size_t(report.M.rows());
  std::vector<double> q0(equilibrium.begin(), equilibrium.begin() + long(n));
  runtime::ExcitedModes excited = runtime::excited_modes(modes, report.M, q0, motion.states, C, ranges, 0.1 * motion.accuracy);
  std::string shares;
  for (std::size_t k = 0; k < excited.share.size(); ++k) shares += fmt::format("{}{:.2g}", k ? ", " : "", excited.share[k]);
  if (excited.kept.size() == n) return {std::nullopt, "the scene excites every mode (shares " + shares + ")"};
  if (excited.kept.empty()) excited.kept.push_back(std::size_t(std::max_element(excited.share.begin(), excited.share.end()) - excited.share.begin()));
  ModalTruncation mt;
  mt.equilibrium = q0, mt.parameter_values = full.problem.parameters;
  Eigen::Map<const Eigen::VectorXd> q(full.initial_state.data(), long(n)), v(full.initial_state.data() + n, long(n));
  Eigen::Map<const Eigen::VectorXd> at(q0.data(), long(n));
  std::vector<std::string> kept;
  for (std::size_t k : excited.kept) {
    const Eigen::VectorXd& shape = modes.modes[k].shape;
    mt.shapes.emplace_back(shape.data(), shape.data() + shape.size());
    mt.mode_numbers.push_back(int(k) + 1);
    mt.initial_modal_coordinates.push_back(shape.dot(report.M * (q - at)));
    mt.initial_modal_rates.push_back(shape.dot(report.M * v));
    kept.push_back(modes.modes[k].rigid_body ? fmt::format("{} (rigid-body motion)", k + 1)
                                             : fmt::format("{} (ω = {:.4g} rad/s)", k + 1, modes.modes[k].omega));
  }
  Equations modal = modal_model(linear, mt);
  // η_k = φ_kᵀ M (q − q0) and η'_k = φ_kᵀ M q' along the reference, for each kept mode
  std::map<std::string, double> sizes;
  for (std::size_t j = 0; j < excited.kept.size(); ++j) {
    Eigen::VectorXd row = report.M * modes.modes[excited.kept[j]].shape;
    double& eta = sizes[modal.symbols.coordinate_names[j]];
    double& rate = sizes[modal.symbols.velocities[j].get_name()];
    for (const std::vector<double>& x : motion.states) {
      Eigen::Map<const Eigen::VectorXd> qt(x.data(), long(n)), vt(x.data() + n, long(n));
      eta = std::max(eta, std::abs(row.dot(qt - at))), rate = std::max(rate, std::abs(row.dot(vt)));
    }
  }
  return {modal, fmt::format("the linear model in {} of its {} modes: {}; the shares of the modes in the outputs: {}", kept.size(), n,
                             joined(kept), shares),
          sizes};
}

}  // namespace eomgen::studies
