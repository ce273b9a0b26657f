/// @file `eomgen bench`: every integrator at a range of tolerances against a reference
/// solution; writes the work-precision charts, the runs and a report with the verdict.
#include "cli/commands.hpp"
#include "studies/bench_study.hpp"

namespace eomgen::cli {

Command add_bench_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("bench", "Work against precision of every integrator, against a reference solution");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--t-end", o->t_end, "End time [s] (default 10)");
  cmd->add_option("--dt-out", o->dt_out, "Output interval the errors are taken at [s] (default t-end/200)");
  cmd->add_option("--integrators", o->integrators, "Comma-separated list, or all (default: every one that applies)");
  cmd->add_option("--tolerances", o->tolerances, "Relative tolerances FROM:TO:FACTOR (default 1e-3:1e-12:10); atol = rtol/100, or 1e-2 rtol of a state's size where smaller");
  cmd->add_option("--step-count", o->step_count, "Fixed steps of rk4 and verlet: dt-out/4 halved this many times less one (default 8)");
  cmd->add_option("--energy-horizon", o->energy_horizon, "Long run for the energy chart [s] (default 100 t-end)");
  cmd->add_option("--energy-tolerance", o->energy_tolerance, "rtol of the long run (default 1e-6)");
  cmd->add_option("--energy-step", o->energy_step, "Fixed step of the long run (default dt-out/5)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--initial", o->initials, "Initial value, one per flag: --initial phi1=2 --initial 'der(phi1)=0'");
  cmd->add_option("--horizon", o->horizon_integrator,
                  "Also the accuracy horizon with this integrator: for each tolerance, the time until the runs at rtol "
                  "and rtol/10 differ by 1e-2 (for chaotic motions)");
  cmd->add_option("-o,--output", o->directory, "Folder for report.md, runs.csv and the charts (default bench-MODEL)");
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    return bench(*o);
  };
}

}  // namespace eomgen::cli
