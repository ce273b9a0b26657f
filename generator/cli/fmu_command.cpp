/// @file `eomgen fmu MODEL [-o DIR] [--kind me|cs|both]`: the model as an FMU (FMI 2.0) for
/// Simulink, Dymola, OpenModelica, FMPy and co-simulation masters (studies/fmu_package.hpp).
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "studies/fmu_package.hpp"
#include "common/output_file.hpp"
#include "pipeline.hpp"

namespace eomgen::cli {

namespace {

int fmu(const std::string& model, const std::string& directory, const std::string& kind) {
  if (std::string failure = make_output_directory(directory); !failure.empty()) {
    std::cerr << "eomgen: error: " << failure << "\n";
    return exit_user_error;
  }
  Derivation d = derive_model_file(model);
  if (report_diagnostics(d.diagnostics, model)) return exit_user_error;
  FmuKinds kinds{kind != "cs", kind != "me"};
  std::cerr << fmt::format("eomgen: building the FMU of {}\n", d.equations->model_name);
  std::string path;
  if (std::string failure = write_fmu(*d.equations, directory, kinds, path); !failure.empty()) {
    std::cerr << "eomgen: error: " << failure << "\n";
    return exit_user_error;
  }
  const Equations& e = *d.equations;
  std::cerr << fmt::format("eomgen: wrote {} (FMI 2.0, {}; {} states, {} parameters, {} inputs, {} outputs)\n", path,
                           kind == "me" ? "Model Exchange" : kind == "cs" ? "Co-Simulation with CVODE" : "Model Exchange and Co-Simulation with CVODE",
                           e.symbols.num_coordinates() + e.num_velocities(), e.symbols.parameters.size(), e.symbols.inputs.size(),
                           e.outputs.size());
  if (e.outputs.empty())
    std::cerr << "eomgen: warning: the model has no [outputs]: an importing tool sees its states as local variables "
                 "only, and nothing to connect\n  hint: name what to measure in [outputs] (e.g. tip_x = \"l*sin(phi)\")\n";
  return exit_success;
}

}  // namespace

Command add_fmu_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("fmu", "Write the model as an FMU (FMI 2.0): NAME.fmu for Model Exchange and Co-Simulation");
  auto model = std::make_shared<std::string>(), directory = std::make_shared<std::string>("."),
       kind = std::make_shared<std::string>("both");
  cmd->add_option("MODEL", *model, "Model file (TOML)")->required();
  cmd->add_option("-o,--output-dir", *directory, "Folder for NAME.fmu (default: the current folder)");
  cmd->add_option("--kind", *kind, "me (Model Exchange), cs (Co-Simulation, CVODE inside) or both (default)")
      ->check(CLI::IsMember({"me", "cs", "both"}));
  return [cmd, model, directory, kind]() -> int {
    if (!cmd->parsed()) return -1;
    return fmu(*model, *directory, *kind);
  };
}

}  // namespace eomgen::cli
