/// @file `eomgen ensemble`: Monte-Carlo simulation of a model over distributions of its
/// parameters, inputs and initial values, on all cores and, under mpirun, on every rank;
/// the statistics of the recorded signals over time and of scalar measures per sample.
#include "cli/commands.hpp"
#include "studies/ensemble_study.hpp"

namespace eomgen::cli {

Command add_ensemble_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("ensemble", "Monte-Carlo simulation over distributions of parameters and initial values");
  auto o = std::make_shared<EnsembleOptions>();
  o->settings.integrator = "auto";
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--samples", o->samples, "Number of samples (default 100)");
  cmd->add_option("--vary", o->vary,
                  "A parameter, input or initial value drawn per sample, one per flag: --vary 'm=normal(1,0.05)', "
                  "--vary 'phi=uniform(0.4,0.6)', --vary 'k=lognormal(0,0.1)' (of log k)");
  cmd->add_option("--outputs", o->outputs, "Signals whose statistics over time are written: outputs, states or energy "
                                           "(default: the model's outputs, else its coordinates)")
      ->delimiter(',');
  cmd->add_option("--measure", o->measures,
                  "A number per sample, one per flag: final(S), max(S), min(S), mean(S) (time average), period(S) (mean "
                  "time between upward crossings of the midrange)");
  cmd->add_option("--quantiles", o->quantiles, "Probabilities of the quantiles (default 0.05,0.5,0.95)");
  cmd->add_option("--seed", o->seed, "Seed of the draws (default 1): sample k's draws depend on it and k only");
  cmd->add_option("--t-end", o->settings.t_end, "End time [s] (default 10)");
  cmd->add_option("--dt-out", o->settings.dt_out, "Output interval [s] (default 0.01)");
  cmd->add_option("--integrator", o->settings.integrator, "As for simulate (default auto, chosen once at the base values)");
  cmd->add_option("--rtol", o->settings.rtol, "Relative tolerance (default 1e-8)");
  cmd->add_option("--atol", o->settings.atol, "Absolute tolerance, one for every state (default: as for simulate, from each sample's states' sizes)");
  cmd->add_option("--step", o->settings.step, "Fixed step of rk4, verlet and gauss-legendre [s] (default dt-out/10)");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--initial", o->initials, "Initial value, one per flag: --initial phi=0.3");
  cmd->add_option("--threads", o->threads, "Threads per process (default: all cores)");
  cmd->add_option("-o,--output", o->csv, "CSV: t, then mean, sd and quantiles of each signal");
  cmd->add_option("--plot", o->plot, "Band chart (PNG): mean, ± one sd and the outer quantiles of each signal over time");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    o->atol_given = cmd->count("--atol") > 0;
    return run_ensemble(*o);
  };
}

}  // namespace eomgen::cli
