// eomgen animate MODEL [-o FILE.html] [simulate's options] [--trace NAME] [--axes]: the run as a
// 3-D animation in one HTML file; `simulate --animate FILE.html` writes the same beside its CSV.
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "common/output_file.hpp"

namespace eomgen::cli {

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

void add_animation_options(CLI::App* cmd, SimulationOptions& o) {
  cmd->add_option("--trace", o.trace, "Draw the path of a body or [[points]] entry, one per flag: --trace bob2")
      ->allow_extra_args(false);
  cmd->add_flag("--axes", o.axes, "Draw each body's and frame's axes (x red, y green, z blue)");
}

Command add_animate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("animate", "Simulate a model and write its motion as a 3-D animation in one HTML file");
  auto o = std::make_shared<SimulationOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML), or a robot's MJCF or URDF file")->required();
  add_simulation_options(cmd, *o);
  cmd->remove_option(cmd->get_option("--output"));
  cmd->add_option("-o,--output", o->animation, "The HTML file to write (default: the model's name with .html)");
  add_animation_options(cmd, *o);
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    o->t_end_given = cmd->count("--t-end") > 0, o->dt_out_given = cmd->count("--dt-out") > 0;
    o->animate_only = true;
    return simulate_model(*o);
  };
}

}  // namespace eomgen::cli
