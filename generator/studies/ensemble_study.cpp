/// @file `eomgen ensemble`: Monte-Carlo simulation of a model over distributions of its
/// parameters, inputs and initial values, on all cores and, under mpirun, on every rank;
/// the statistics of the recorded signals over time and of scalar measures per sample.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <mutex>

#include <fmt/format.h>

#include "analyse/integrator_choice.hpp"
#include "common/count_progress.hpp"
#include "common/output_file.hpp"
#include "common/stop_signal.hpp"
#include "derive/initial_state.hpp"
#include "distribute/distributed_ensemble.hpp"
#include "report/reports.hpp"
#include "studies/ensemble_options.hpp"
#include "studies/ensemble_output.hpp"
#include "studies/ensemble_study.hpp"
#include "studies/exit_status.hpp"
#include "studies/ranked_run.hpp"

namespace eomgen::studies {

namespace {

// the setup from the flags, or the exit status after saying what is wrong
std::optional<int> build_setup(const EnsembleOptions& o, const LoadedProblem& loaded, runtime::EnsembleSetup& setup) {
  const eomgen_model_abi& m = *loaded.compiled->abi();
  setup.base = loaded.problem;
  setup.initial_state = loaded.initial_state;
  setup.settings = o.settings;
  setup.state_tolerances = !o.atol_given;
  setup.seed = o.seed;
  std::vector<bool> given;
  if (!assign_states(m, o.initials, "--initial", setup.initial_state, &given)) return exit_user_error;
  for (const std::string& text : o.vary) {
    auto v = parse_variation(m, text);
    if (!v) return exit_user_error;
    for (const runtime::Variation& earlier : setup.variations)
      if (earlier.name == v->name) {
        std::cerr << fmt::format("eomgen: error: --vary {}: given twice\n", v->name);
        return exit_user_error;
      }
    setup.variations.push_back(*v);
    // a constrained model keeps a drawn initial value where the constraints allow it
    if (v->target == runtime::Variation::Target::state) given[std::size_t(v->index)] = true;
  }
  setup.settings.given_state = given;
  // initial values written in the parameters follow each sample's; GiNaC is not thread-safe
  setup.initial_state_at = [&equations = loaded.equations](const std::vector<double>& parameters) {
    static std::mutex symbolic;
    std::lock_guard<std::mutex> lock(symbolic);
    std::string failed;
    return initial_state(equations, parameters, failed);
  };
  for (const std::string& text : o.measures) {
    auto measure = parse_measure(m, text);
    if (!measure) return exit_user_error;
    setup.measures.push_back(*measure);
  }
  setup.signals = o.outputs;
  if (setup.signals.empty())  // the model's outputs, else its coordinates
    setup.signals = m.num_outputs ? std::vector<std::string>(m.output_names, m.output_names + m.num_outputs)
                                  : std::vector<std::string>(m.coordinate_names, m.coordinate_names + m.num_coordinates);
  for (const std::string& name : setup.signals)
    if (!check_signal(m, name, "--outputs")) return exit_user_error;
  return std::nullopt;
}

std::optional<int> check_settings(const EnsembleOptions& o, runtime::EnsembleSetup& setup, const eomgen_model_abi& m) {
  runtime::SimulationSettings& s = setup.settings;
  if (o.samples < 1 || o.samples > 100'000'000) {
    std::cerr << "eomgen: error: --samples must be between 1 and 1e8\n";
    return exit_user_error;
  }
  if (!(s.t_end > s.t_start) || !(s.dt_out > 0) || !(s.rtol > 0) || !(s.atol > 0) || s.step < 0) {
    std::cerr << "eomgen: error: need --t-end > 0, --dt-out > 0, --rtol > 0, --atol > 0 and --step >= 0\n";
    return exit_user_error;
  }
  // every sample's recorded signals are kept until rank 0 has them: refuse what cannot fit
  double times = std::floor((s.t_end - s.t_start) / s.dt_out) + 2;
  double bytes = times * double(o.samples) * double(setup.signals.size()) * 8;
  if (bytes > 4e9) {
    std::cerr << fmt::format("eomgen: error: {} samples of {} signals at {:.4g} output times hold {:.3g} GB\n"
                             "  hint: raise --dt-out, record fewer --outputs, or split the study by --seed\n",
                             o.samples, setup.signals.size(), times, bytes / 1e9);
    return exit_user_error;
  }
  if (s.integrator == "auto") {
    runtime::IntegratorChoice choice = runtime::choose_integrator(setup.base, setup.initial_state, s.t_start);
    s.integrator = choice.integrator;
    std::cerr << fmt::format("eomgen: integrator {}: {} (--integrator chooses another)\n", choice.integrator, choice.reason);
  }
  if (std::string refusal = runtime::integrator_refusal(m, s.integrator); !refusal.empty()) {
    std::cerr << fmt::format("eomgen: error: --integrator {}: {}\n", s.integrator, refusal);
    return exit_user_error;
  }
  return std::nullopt;
}

void report_failures(const distribute::EnsembleResult& r, const runtime::EnsembleSetup& setup) {
  if (r.failed == 0) return;
  std::string draws;
  for (std::size_t i = 0; i < setup.variations.size() && i < r.first_failed_drawn.size(); ++i)
    draws += fmt::format("{}{} = {:.10g}", i ? ", " : "", setup.variations[i].name, r.first_failed_drawn[i]);
  std::cerr << fmt::format("eomgen: warning: {} of {} runs failed and are left out of the statistics; the first, sample {} "
                           "({}): {}\n",
                           r.failed, r.samples, r.first_failed, draws.empty() ? "no draws" : draws, r.first_failure);
}

}  // namespace

int run_ensemble(const EnsembleOptions& o) {
  const distribute::Ranks& ranks = distribute::Ranks::world();
  QuietUnlessRoot quiet(ranks);
  // the files are rank 0's to write: only its file system counts
  for (const std::string* path : {&o.csv, &o.plot})
    if (std::string refusal = refusal_on_root(ranks, [&] { return path->empty() ? "" : output_file_refusal(*path); });
        !refusal.empty()) {
      std::cerr << "eomgen: error: " << (path == &o.csv ? "-o" : "--plot") << ": " << refusal << "\n";
      return exit_user_error;
    }
  auto probabilities = parse_probabilities(o.quantiles);
  if (!probabilities) return exit_user_error;
  LoadedProblem loaded;
  if (auto status = load_on_every_rank(ranks, o.model, o.sets, loaded)) return *status;
  const eomgen_model_abi& m = *loaded.compiled->abi();
  runtime::EnsembleSetup setup;
  if (auto status = build_setup(o, loaded, setup)) return *status;
  if (auto status = check_settings(o, setup, m)) return *status;
  std::cerr << fmt::format("eomgen: ensemble of {} samples of {} on {}\n", o.samples, m.name, ranks.description());
  distribute::EnsembleResult result;
  {
    StopOnSignal stop;
    result = distribute::distributed_ensemble(ranks, setup, o.samples, *probabilities, o.threads,
                                              count_progress("ensemble", ranks.size() > 1 ? "samples, rank 0's share" : "samples"), StopOnSignal::flag());
  }
  if (result.interrupted) {
    std::cerr << "\neomgen ensemble: interrupted; no statistics of a part of the samples are written\n";
    return exit_numerical_failure;
  }
  if (!ranks.is_root()) return result.failed == result.samples ? exit_numerical_failure : exit_success;
  report_failures(result, setup);
  if (result.failed == result.samples) {
    std::cerr << "eomgen: every run failed: no statistics\n";
    return exit_numerical_failure;
  }
  if (!o.csv.empty())
    if (std::string failure = write_file_atomically(o.csv, ensemble_csv(result, *probabilities)); !failure.empty()) {
      std::cerr << "eomgen: " << failure << "\n";
      return exit_user_error;
    }
  if (!o.plot.empty()) {
    std::string title = fmt::format("{}: ensemble of {} samples", m.name, o.samples);
    if (std::string failure = runtime::draw_ensemble_bands(title, result.times, result.bands, *probabilities, o.plot);
        !failure.empty())
      std::cerr << "eomgen: warning: no chart: " << failure << "\n";
  }
  EnsembleDescription d{m.name, setup.settings.integrator, &setup, *probabilities, ranks.description(), ranks.size()};
  if (o.json) print_ensemble_json(result, d);
  else print_ensemble_text(result, d);
  return exit_success;
}

}  // namespace eomgen::studies
