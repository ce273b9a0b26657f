/// @file `eomgen sweep`: the eigenvalues along one parameter with the crossings of the
/// imaginary axis, or a stability map over two parameters, on all cores, with the
/// symbolic boundary over it when asked.
#include "cli/commands.hpp"
#include "studies/sweep_study.hpp"

namespace eomgen::cli {

Command add_sweep_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("sweep", "Eigenvalues along one parameter, or a stability map over two");
  auto o = std::make_shared<SweepOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--param", o->params,
                  "Swept parameter, once (eigenvalues along it: --param v=0:10:1001) or twice (a map: --param b=0.05:2:200 "
                  "--param J=0.05:3:200); :log after the count spaces the points by a constant ratio (--param d=1e-9:1e3:121:log)");
  cmd->add_option("--at", o->at, "A fixed equilibrium, one value per flag (default: re-found at every point)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_flag("--symbolic", o->symbolic, "Draw the boundary of the symbolic Hurwitz conditions over the map");
  cmd->add_option("--threads", o->threads, "Threads (default: all cores)");
  cmd->add_option("-o,--output", o->csv, "CSV: the eigenvalues at each value, or the map (x, y, stability degree)");
  cmd->add_option("--plot", o->plot, "Chart as PNG: the eigenvalues against the parameter, or the map");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return run_sweep(*o);
  };
}

}  // namespace eomgen::cli
