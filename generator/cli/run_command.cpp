#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "studies/bench_study.hpp"
#include "studies/stability_study.hpp"
#include "common/output_file.hpp"

namespace eomgen::cli {

// models/ of the working directory, then the installed share/eomgen/models beside the
// executable's bin/, and last the source tree this eomgen was built from
std::string default_model_path() {
  const std::string name = "double_pendulum.toml";
  if (std::filesystem::exists("models/" + name)) return "models/" + name;
  std::error_code ignored;
  std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ignored);
  if (!executable.empty()) {
    std::filesystem::path installed = executable.parent_path().parent_path() / "share" / "eomgen" / "models" / name;
    if (std::filesystem::exists(installed, ignored)) return installed.lexically_normal().string();
  }
  return std::string(EOMGEN_MODELS_DIR) + "/" + name;
}

Command add_run_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "run",
      "The main job on a model (default: the double pendulum): derive and print its equations, generate its header, "
      "compile it, simulate it, animate it, check the stability of its equilibrium, draw its charts and the work-precision chart");
  auto model = std::make_shared<std::string>();
  auto directory = std::make_shared<std::string>("eomgen-run");
  cmd->add_option("MODEL", *model, "Model file (TOML); default models/double_pendulum.toml");
  cmd->add_option("-o,--output-dir", *directory, "Folder for the header, the trajectory and the charts (default eomgen-run)");
  return [cmd, model, directory]() -> int {
    if (!cmd->parsed()) return -1;
    std::string path = model->empty() ? default_model_path() : *model;
    std::cerr << "eomgen run: " << path << "\n";
    if (int status = derive_and_write(path, "text", ""); status != exit_success) return status;
    if (std::string failure = make_output_directory(*directory); !failure.empty()) {
      std::cerr << "eomgen: error: " << failure << "\n";
      return exit_user_error;
    }
    std::string stem = std::filesystem::path(path).stem().string();
    SimulationOptions o;
    o.model = path;
    o.header_dir = *directory;
    o.csv = *directory + "/" + stem + ".csv";
    o.plot = *directory + "/" + stem + ".png";
    o.animation = *directory + "/" + stem + ".html";
    o.animation_if_drawn = true;
    o.settings.integrator = "auto";
    o.settings.rtol = 1e-10;
    o.settings.atol = 1e-12;
    if (int status = simulate_model(o); status != exit_success) return status;
    std::cerr << "eomgen run: stability of the equilibrium nearest the initial values\n";
    if (int status = stability_of_model(path); status != exit_success)
      std::cerr << "eomgen run: (no stability report for this model)\n";
    std::cerr << "eomgen run: work against precision of every integrator\n";
    int status = bench_model(path, *directory + "/bench");
    std::cerr << "eomgen run: header, trajectory, animation, charts and the work-precision report are in " << *directory << "/\n";
    return status;
  };
}

}  // namespace eomgen::cli
