/// @file `eomgen linear`: the linearized system about an equilibrium or steady motion
/// (found as `stability` finds it), solved: eigenvalues with multiplicities and Jordan
/// blocks, natural frequencies and mass-normalized modes, and Φ(t) = e^{At} (Hiller §6, §8.1).
#include "cli/commands.hpp"
#include "studies/linear_study.hpp"

namespace eomgen::cli {

Command add_linear_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("linear", "The linearized system about an equilibrium, solved: eigenvalues with "
                                               "Jordan structure, natural modes, fundamental matrix");
  auto o = std::make_shared<LinearOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--at", o->at, "Equilibrium value, one per flag, as for `stability` (default: searched from the "
                  "model's initial values)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--outputs", o->outputs, "Outputs y = C x + D u for observability: states or [outputs] by name, "
                  "comma-separated (default: the model's [outputs])");
  cmd->add_option("--transfer", o->transfer, "Transfer function from an input to an output (a state or an [outputs] "
                  "entry), one pair per flag: --transfer F:x");
  cmd->add_option("--times", o->times, "Times at which to print the fundamental matrix Phi(t) = e^(At): --times 0.5,1,10");
  cmd->add_flag("--symbolic", o->symbolic, "Phi(t) and the --transfer functions G(s) in closed form, in the parameters "
                "where the characteristic polynomial factors into linear and quadratic factors over them, else at their "
                "values (Lagrange II models with exact A)");
  cmd->add_option("--response", o->response.response, "Response of the linearized system, written as CSV of the "
                  "deviations from the equilibrium: initial (with --initial), impulse:INPUT, step:INPUT (unit), "
                  "harmonic:INPUT:OMEGA (sin(OMEGA t))");
  cmd->add_option("--input", o->response.input, "Response to one input as a function of time: --input 'F=step(2)' (a unit "
                  "step at t = 2), 'F=0.5*impulse(0)', 'F=sin(3*t)', 'F=2*cos(3*t)'");
  cmd->add_option("--initial", o->response.initials, "Initial deviation, one per flag: --initial x1=0.01");
  cmd->add_option("--t-end", o->response.t_end, "End time of the response [s] (default 10; a warning where the slowest "
                  "mode takes longer)");
  cmd->add_option("--dt-out", o->response.dt_out, "Output interval of the response [s] (default 0.01; a warning where "
                  "that skips half a period)");
  cmd->add_option("-o,--output", o->response.csv, "CSV file for the response (default: standard output)");
  cmd->add_option("--plot", o->response.plot, "Charts (PNG): with --response the response's coordinates; otherwise "
                  "FILE_modes.png (the mode shapes) and FILE_bode_U_Y.png for each --bode pair");
  cmd->add_option("--bode", o->bode, "Bode chart of a transfer function, one pair per flag: --bode F:x (with --plot)");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    o->response.t_end_given = cmd->count("--t-end") > 0, o->response.dt_out_given = cmd->count("--dt-out") > 0;
    return linear(*o);
  };
}

}  // namespace eomgen::cli
