/// @file `eomgen stability`: the equilibrium, its linearization split by force
/// type, eigenvalues, verdict, modes, Hurwitz test, the classical theorems that
/// apply, and with --symbolic the stability conditions in the parameters.
#include "cli/commands.hpp"
#include "studies/stability_study.hpp"

namespace eomgen::cli {

Command add_stability_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("stability", "Equilibrium, linearization and stability of a model");
  auto o = std::make_shared<StabilityOptions>();
  cmd->add_option("MODEL", o->model, "Model file (TOML)")->required();
  cmd->add_option("--at", o->at, "Equilibrium value, one per flag: --at theta=0 --at 'der(phi)=8'; velocities not named "
                  "are zero, other coordinates as in the model, and where that does not balance, those and "
                  "the cyclic velocities not named are solved for. --at p_phi=VALUE holds the momentum of the cyclic coordinate phi and analyses Routh's "
                  "reduced system");
  cmd->add_option("--set", o->sets, "Parameter or input value, one per flag: --set m=2.5");
  cmd->add_option("--period", o->period, "Period T [s] of time-periodic equations (default: found from sin/cos(w*t) in "
                  "the model); their stability is judged by Floquet multipliers over T")->check(positive_number());
  cmd->add_option("--symbolic", o->symbolic, "Keep these parameters as symbols and print the Hurwitz conditions: --symbolic b,J");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return stability(*o);
  };
}
}  // namespace eomgen::cli
