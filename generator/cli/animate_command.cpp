// eomgen animate MODEL [-o FILE.html] [simulate's options] [--trace NAME] [--axes]: the run as a
// 3-D animation in one HTML file; `simulate --animate FILE.html` writes the same beside its CSV.
#include "cli/commands.hpp"

namespace eomgen::cli {

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
    o->atol_given = cmd->count("--atol") > 0;
    o->animate_only = true;
    return simulate_model(*o);
  };
}

}  // namespace eomgen::cli
