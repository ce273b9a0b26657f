/// @file `eomgen simulate`, `animate` and `run`'s simulation: derive, compile (cached), simulate
/// with the rows streaming to the CSV and the animation, then the charts and the summary.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "analyse/baumgarte_scale.hpp"
#include "analyse/conservation.hpp"
#include "analyse/integrator_choice.hpp"
#include "analyse/output_interval.hpp"
#include "analyse/state_tolerances.hpp"
#include "analyse/work_precision.hpp"
#include "common/output_file.hpp"
#include "common/stop_signal.hpp"
#include "compile/compile_cache.hpp"
#include "emit/cpp_header.hpp"
#include "emit/formats.hpp"
#include "pipeline.hpp"
#include "report/reports.hpp"
#include "simulation.hpp"
#include "studies/exit_status.hpp"
#include "studies/input_signal.hpp"
#include "studies/loaded_problem.hpp"
#include "studies/simulation_report.hpp"
#include "studies/simulation_run.hpp"
#include "studies/trajectory_output.hpp"

namespace eomgen::studies {

namespace {

// an explicit method on a stiff model: its steps are set by stability, not by accuracy
void stiffness_warning(const runtime::Problem& p, const std::vector<double>& x0, const runtime::SimulationSettings& s,
                       const runtime::SimulationResult& r) {
  if (!runtime::is_explicit_integrator(s.integrator)) return;
  double ratio = runtime::stiffness_ratio(p, x0, s.t_start);
  if (!(ratio > 1e3)) return;
  std::cerr << fmt::format("eomgen: warning: the model is stiff (stiffness ratio {:.2g} at the start: its fastest decay "
                           "is that many times quicker than its slowest motion); {} is limited by stability there, not by "
                           "accuracy, and took {} steps: cvode-bdf or arkode-dirk take far fewer\n",
                           ratio, s.integrator, r.statistics.steps);
}

// Baumgarte's gains far from the system's rate (analyse/baumgarte_scale.hpp): much faster, they
// make the equations stiff; much slower, they correct nothing between projections
void baumgarte_warning(const runtime::Problem& p, const std::vector<double>& x0, const runtime::SimulationSettings& s) {
  const eomgen_model_abi& m = *p.model;
  if (!s.baumgarte || m.num_multipliers == 0 || runtime::is_dae_integrator(s.integrator)) return;
  double alpha = s.baumgarte_alpha >= 0 ? s.baumgarte_alpha : m.baumgarte_alpha;
  double beta = s.baumgarte_beta >= 0 ? s.baumgarte_beta : m.baumgarte_beta;
  double ratio = runtime::baumgarte_gain_ratio(p, x0, alpha, beta);
  if (ratio <= 1e3 && ratio >= 1e-3) return;
  std::cerr << fmt::format("eomgen: warning: Baumgarte's gains (alpha {:g}, beta {:g} 1/s{}) are {:.2g} times the system's "
                           "rate: {}; --baumgarte-alpha and --baumgarte-beta near the system's rate ({:.3g} 1/s), or "
                           "--stabilization projection, keep the constraints without that\n",
                           alpha, beta, s.baumgarte_alpha < 0 && s.baumgarte_beta < 0 ? ", the model's" : "", ratio,
                           ratio > 1 ? "a constraint error decays that much faster than the motion, which makes the "
                                       "equations stiff and a run at tight tolerances unreliable"
                                     : "a constraint error is corrected that much more slowly than the motion, which is "
                                       "no correction at all",
                           std::max(alpha, beta) / ratio);
}

// the scene's time span and output interval, unless given on the command line
void apply_scene_times(const Equations& e, SimulationOptions& o) {
  for (const Scene& scene : e.scenes)
    if (scene.name == o.scene) {
      if (!o.t_end_given) o.settings.t_end = scene.t_end;
      if (!o.dt_out_given) o.settings.dt_out = scene.dt_out;
      std::cerr << fmt::format("eomgen: scene {}: to t = {:g}, output every {:g} s\n", scene.name, o.settings.t_end,
                               o.settings.dt_out);
    }
}

// without --atol, each state's absolute tolerance from its own size (analyse/state_tolerances.hpp);
// said where that is a tenth of the default or less (a state far below a unit in size)
void scale_absolute_tolerances(const runtime::Problem& problem, const std::vector<double>& x0,
                               runtime::SimulationSettings& settings) {
  const eomgen_model_abi& m = *problem.model;
  settings.state_atol = runtime::state_absolute_tolerances(problem, x0, settings.rtol, settings.atol);
  std::string tighter;
  int shown = 0;
  for (std::size_t i = 0; i < settings.state_atol.size(); ++i)
    if (settings.state_atol[i] <= 0.1 * settings.atol && shown++ < 6)
      tighter += fmt::format("{}{} {:.2g}", tighter.empty() ? "" : ", ", m.state_names[i], settings.state_atol[i]);
  if (!tighter.empty())
    std::cerr << fmt::format("eomgen: absolute tolerance from each state's size where below {:g}: {}{} (--atol sets one "
                             "for all)\n", settings.atol, tighter, shown > 6 ? ", …" : "");
}

}  // namespace

int simulate_model(const SimulationOptions& options) {
  SimulationOptions o = options;
  // the files before the run that fills them
  for (const std::string* file : {&o.csv, &o.animation})
    if (std::string refusal = file->empty() ? "" : output_file_refusal(*file); !refusal.empty()) {
      std::cerr << "eomgen: error: " << (file == &o.csv || o.animate_only ? "-o" : "--animate") << ": " << refusal << "\n";
      return exit_user_error;
    }
  LoadedProblem loaded;
  if (auto status = load_problem(o.model, o.sets, loaded, {}, {o.scene, o.variant, {}})) return *status;
  if (o.animate_only && o.animation.empty()) o.animation = loaded.equations.model_name + ".html";
  if (!o.scene.empty()) apply_scene_times(loaded.equations, o);
  if (!o.header_dir.empty()) {
    if (std::string failure = make_output_directory(o.header_dir); !failure.empty()) {
      std::cerr << "eomgen: error: " << failure << "\n";
      return exit_user_error;
    }
    if (std::string failure = write_file_atomically(o.header_dir + "/" + loaded.equations.model_name + ".hpp", loaded.header);
        !failure.empty()) {
      std::cerr << "eomgen: error: " << failure << "\n";
      return exit_user_error;
    }
  }
  const eomgen_model_abi& m = *loaded.compiled->abi();
  runtime::Problem& problem = loaded.problem;
  double table_end = INFINITY;
  if (auto status = set_input_signal(loaded, o.input_signals, o.input_file, table_end)) return *status;
  if (table_end < o.settings.t_end)
    std::cerr << fmt::format("eomgen: warning: {} ends at t = {:g}, before --t-end {:g}: its last values are held\n",
                             o.input_file, table_end, o.settings.t_end);
  std::vector<double> x0 = loaded.initial_state;
  std::vector<bool> given;
  if (!assign_states(m, o.initials, "--initial", x0, &given)) return exit_user_error;
  if (auto status = check_plot_xy(o, m)) return *status;
  if (!(o.settings.t_end > o.settings.t_start) || !(o.settings.dt_out > 0) || !(o.settings.rtol > 0) ||
      !(o.settings.atol > 0) || o.settings.step < 0) {
    std::cerr << "eomgen: error: need --t-end > 0, --dt-out > 0, --rtol > 0, --atol > 0 and --step >= 0\n";
    return exit_user_error;
  }
  // the rows stream to the CSV, so memory is bounded; the disk is not: refuse a run that would fill it
  double rows = std::floor((o.settings.t_end - o.settings.t_start) / o.settings.dt_out) + 2;
  if (!(rows <= o.max_rows)) {
    double columns = 2.0 + double(m.num_states + m.num_outputs + m.num_first_integrals);
    std::cerr << fmt::format("eomgen: error: --t-end {:g} at --dt-out {:g} makes {:.4g} output rows, more than the {:.4g} "
                             "allowed (the CSV would hold about {:.3g} GB)\n  hint: raise --dt-out, or allow more with "
                             "--max-rows\n",
                             o.settings.t_end, o.settings.dt_out, rows, o.max_rows, rows * columns * 24 / 1e9);
    return exit_user_error;
  }
  runtime::SimulationSettings settings = o.settings;
  settings.given_state = given;
  if (settings.integrator == "auto") {
    runtime::IntegratorChoice choice = runtime::choose_integrator(problem, x0, settings.t_start);
    settings.integrator = choice.integrator;
    std::cerr << fmt::format("eomgen: integrator {}: {} (--integrator chooses another)\n", choice.integrator, choice.reason);
  }
  if (!o.atol_given) scale_absolute_tolerances(problem, x0, settings);
  if (!o.dt_out_given)
    if (auto aliased = runtime::aliasing_warning(problem, settings.t_start, x0, settings.dt_out))
      std::cerr << "eomgen: warning: " << *aliased << "\n";
  std::cerr << fmt::format("eomgen: simulating {} with {} to t = {:g}\n", m.name, settings.integrator, o.settings.t_end);
  settings.baumgarte = o.stabilization == "both" || o.stabilization == "baumgarte";
  settings.projection = o.stabilization == "both" || o.stabilization == "projection";
  baumgarte_warning(problem, x0, settings);
  runtime::SimulationResult result;
  TrajectoryOutput output(m, o.csv);
  std::optional<runtime::AnimationRecorder> animation;
  if (!o.animation.empty() && (m.num_drawn_bodies > 0 || !o.animation_if_drawn)) animation.emplace(m, problem.parameters);
  settings.stream = [&output, &animation](const runtime::Trajectory& rows) {
    if (animation) animation->take(rows);
    return output.take(rows);
  };
  // Ctrl-C or a TERM ends the run at the next output time; what was computed is written
  try {
    StopOnSignal stop;
    RunProgress progress("simulate", settings.t_start, settings.t_end);
    settings.stop = &StopOnSignal::flag();
    settings.progress = [&progress](double t) { progress(t); };
    result = runtime::simulate(problem, x0, settings);
  } catch (const std::invalid_argument& why) {
    std::cerr << fmt::format("eomgen: error: --integrator {}: {}\n", settings.integrator, why.what());
    return exit_user_error;
  }
  for (const std::string& w : result.warnings) std::cerr << "eomgen: warning: " << w << "\n";
  stiffness_warning(problem, x0, settings, result);
  if (result.failed && result.summary.rows == 0) {
    std::cerr << fmt::format("eomgen: the simulation cannot start: {}\n", result.failure);
    return exit_numerical_failure;
  }
  bool unforced = !problem.input_signal &&
                  std::all_of(problem.inputs.begin(), problem.inputs.end(), [](double u) { return u == 0; });
  // a model with dissipation whose coefficients are 0 at these values conserves T + V too
  bool conservative = unforced && runtime::energy_conserved_at(problem, settings.t_start, x0);
  if (!output.finish()) {
    std::cerr << "eomgen: " << output.failure() << "\n";
    return exit_user_error;
  }
  if (animation)
    if (auto status = write_animation(*animation, o)) return *status;
  if (!o.plot.empty()) draw_all_charts(o, m, output.chart_rows(), conservative);
  print_summary(settings, m, result, conservative, unforced, o.json, loaded.compiled->reference_scalar);
  if (result.failed) {
    std::cerr << fmt::format(result.interrupted ? "eomgen: the simulation was {}\n" : "eomgen: the simulation failed: {}\n",
                             result.failure);
    if (!o.csv.empty())
      std::cerr << fmt::format("eomgen: {} holds the {} rows computed before the {}\n", o.csv, result.summary.rows,
                               result.interrupted ? "interruption: a partial run" : "failure");
    return exit_numerical_failure;
  }
  return exit_success;
}

std::optional<int> write_animation(const runtime::AnimationRecorder& recorder, const SimulationOptions& o) {
  runtime::AnimationSettings settings;
  settings.title = recorder.model().name;
  settings.trace = o.trace;
  settings.axes = o.axes;
  std::string error;
  std::string page = runtime::animation_page(recorder, settings, error);
  if (!error.empty()) {
    std::cerr << "eomgen: error: --animate: " << error << "\n";
    return exit_user_error;
  }
  if (std::string failure = write_file_atomically(o.animation, page); !failure.empty()) {
    std::cerr << "eomgen: error: " << failure << "\n";
    return exit_user_error;
  }
  std::cerr << fmt::format("eomgen: wrote {} ({} frames, {:.2g} MB): open it in a browser; {}#t=1.5 opens it paused at t = 1.5\n",
                           o.animation, recorder.frames(), double(page.size()) / 1e6, o.animation);
  return std::nullopt;
}

}  // namespace eomgen::studies
