/// @file `eomgen simulate`, `animate` and `run`'s simulation: derive, compile (cached), simulate
/// with the rows streaming to the CSV and the animation, then the charts and the summary.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/animation.hpp"
#include "simulation.hpp"

namespace eomgen::studies {

struct SimulationOptions {
  std::string model;
  runtime::SimulationSettings settings;
  std::vector<std::string> sets, initials;
  std::vector<std::string> input_signals;  // --input NAME=EXPRESSION in t
  std::string input_file;                  // --input-file table.csv
  std::string csv, plot, header_dir;
  std::string plot_xy;  // "X,Y": also Y against X
  std::string stabilization = "both";  // constrained models: both, baumgarte, projection or none
  bool json = false;
  std::string scene, variant;          // --scene NAME, --variant NAME
  bool t_end_given = false, dt_out_given = false;  // a scene's times give way to --t-end, --dt-out
  bool atol_given = false;  // without --atol each state's own size sets its absolute tolerance
  double max_rows = 1e6;  // output rows a run may keep in memory (--max-rows)
  std::string animation;           // --animate FILE.html (animate: -o)
  std::vector<std::string> trace;  // --trace NAME: bodies whose paths the animation draws
  bool axes = false;               // --axes
  bool animate_only = false;        // `eomgen animate`: the page is the result (named after the model by default)
  bool animation_if_drawn = false;  // `eomgen run`: no page (and no error) for a model that draws nothing
};

/// Derives, generates, compiles (cached) and simulates; writes the CSV, the charts and the
/// animation asked for; prints the summary. Returns the exit status.
int simulate_model(const SimulationOptions& options);

/// Writes the animation page of a run to o.animation; the exit status when it cannot.
std::optional<int> write_animation(const runtime::AnimationRecorder& recorder, const SimulationOptions& o);

}  // namespace eomgen::studies
