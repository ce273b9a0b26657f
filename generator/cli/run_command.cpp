#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"

namespace eomgen::cli {

std::string default_model_path() {
  const std::string name = "double_pendulum.toml";
  if (std::filesystem::exists("models/" + name)) return "models/" + name;
  return std::string(EOMGEN_MODELS_DIR) + "/" + name;
}

Command add_run_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "run", "The main job on a model (default: the double pendulum): derive its equations and print them");
  auto model = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model, "Model file (TOML); default models/double_pendulum.toml");
  return [cmd, model]() -> int {
    if (!cmd->parsed()) return -1;
    std::string path = model->empty() ? default_model_path() : *model;
    std::cerr << "eomgen run: " << path << "\n";
    return derive_and_write(path, "text", "");
  };
}

}  // namespace eomgen::cli
