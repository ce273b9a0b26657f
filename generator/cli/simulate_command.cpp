/// @file `eomgen simulate` and the simulation options `animate` and `run` share.
#include "cli/commands.hpp"
#include "studies/simulation_run.hpp"

namespace eomgen::cli {

void add_simulation_options(CLI::App* cmd, SimulationOptions& o) {
  cmd->add_option("--t-end", o.settings.t_end, "End time [s] (default 10)");
  cmd->add_option("--dt-out", o.settings.dt_out, "Output interval [s] (default 0.01)");
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all{"auto"};
    for (const std::string& n : runtime::integrator_names()) all.push_back(n);
    return all;
  }();
  o.settings.integrator = "auto";
  cmd->add_option("--integrator", o.settings.integrator,
                  "auto (default: cvode-bdf for constrained or stiff models, else arkode-dp5; the choice is printed), "
                  "cvode-bdf, cvode-adams, arkode-dp5, arkode-verner, arkode-dirk, rk4, verlet (in canonical variables for a "
                  "separable H), gauss-legendre (implicit, symplectic, order 4), "
                  "ida (Lagrange I models, as a differential-algebraic system), reference (extrapolation in a wide scalar, "
                  "with its own error estimate)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--rtol", o.settings.rtol, "Relative tolerance (default 1e-8)");
  cmd->add_option("--atol", o.settings.atol, "Absolute tolerance, one for every state (default: 1e-10, or 1e-2 rtol of a state's "
                  "size where that is smaller: its initial value (or default where that is 0), for a velocity also its coordinate's times the "
                  "system's rate)");
  cmd->add_option("--step", o.settings.step, "Fixed step of rk4, verlet and gauss-legendre [s] (default dt-out/10)");
  cmd->add_option("--max-rows", o.max_rows, "Most output rows a run may keep (default 1e6): longer runs need a longer --dt-out");
  cmd->add_option("--stabilization", o.stabilization,
                  "Constrained models: both (default), baumgarte (Lagrange I), projection (after every step) or none; "
                  "with projection (and both) the quaternions of ball and free joints are normalized after every step")
      ->check(CLI::IsMember({"both", "baumgarte", "projection", "none"}));
  cmd->add_option("--baumgarte-alpha", o.settings.baumgarte_alpha, "Baumgarte's damping gain [1/s] (default: the model's, 10)");
  cmd->add_option("--baumgarte-beta", o.settings.baumgarte_beta, "Baumgarte's stiffness gain [1/s] (default: the model's, 10)");
  cmd->add_option("--set", o.sets, "Parameter or input value, one per flag: --set m=2.5")->allow_extra_args(false);
  cmd->add_option("--initial", o.initials, "Initial value, one per flag: --initial phi=0.3 --initial 'der(phi)=1'")->allow_extra_args(false);
  cmd->add_option("--input", o.input_signals, "An input as a function of time, one per flag: --input 'tau=0.5*sin(2*t)' "
                  "(t and the parameters may appear)")->allow_extra_args(false);
  cmd->add_option("--input-file", o.input_file, "Inputs from a CSV table: header t,NAME,..., rows with increasing t; "
                  "linear interpolation, end values held");
  cmd->add_option("--scene", o.scene, "Run the model's [scenes.NAME] as written: its inputs, parameters, initial state, "
                  "t_end and dt_out (--set, --initial, --t-end and --dt-out still override)");
  cmd->add_option("--variant", o.variant, "Simulate the model's [variants.NAME] instead of the full model");
  cmd->add_option("-o,--output", o.csv, "Trajectory CSV file");
  cmd->add_option("--plot", o.plot, "Chart of the coordinates (PNG); conservative models also get NAME_energy.png, "
                  "models with outputs NAME_outputs.png");
  cmd->add_option("--plot-xy", o.plot_xy, "Also NAME_xy.png: Y against X, two columns of the trajectory (coordinates, "
                  "velocities, outputs, energy, t): --plot-xy tip_x,tip_y");
}

Command add_simulate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("simulate", "Generate, compile (cached) and simulate a model");
  auto o = std::make_shared<SimulationOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  add_simulation_options(cmd, *o);
  cmd->add_option("--animate", o->animation, "Also write the motion as a 3-D animation, one HTML file (see `eomgen animate`)");
  add_animation_options(cmd, *o);
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "Summary format: text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    o->t_end_given = cmd->count("--t-end") > 0, o->dt_out_given = cmd->count("--dt-out") > 0;
    o->atol_given = cmd->count("--atol") > 0;
    return simulate_model(*o);
  };
}

}  // namespace eomgen::cli
