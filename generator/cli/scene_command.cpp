/// @file `eomgen scene MODEL NAME`: the cheapest model and integrator that answer the
/// scene to its accuracy (studies/scene_analysis.hpp), printed and, with -o, written out.
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "studies/scene_analysis.hpp"
#include "studies/scene_report.hpp"
#include "common/stop_signal.hpp"
#include "common/output_file.hpp"

namespace eomgen::cli {

namespace {

int scene(const std::string& model, const std::string& name, const std::string& directory, bool json) {
  // the folder before the work that fills it
  if (std::string failure = directory.empty() ? "" : make_output_directory(directory); !failure.empty()) {
    std::cerr << "eomgen: error: " << failure << "\n";
    return exit_user_error;
  }
  StopOnSignal stop;
  SceneAnalysis a = analyse_scene(model, name, [](const std::string& line) { std::cerr << "eomgen: " << line << "\n"; },
                                  &StopOnSignal::flag());
  if (a.interrupted && a.runs.empty()) {
    std::cerr << "eomgen: scene interrupted (SIGINT or SIGTERM) before any candidate ran: nothing written\n";
    return exit_numerical_failure;
  }
  if (!a.refusal.empty()) {
    std::cerr << a.refusal << (a.refusal.back() == '\n' ? "" : "\n");
    return exit_user_error;
  }
  json ? print_scene_json(a) : print_scene_text(a);
  if (!directory.empty()) {
    if (std::string failure = write_scene_files(a, directory); !failure.empty()) {
      std::cerr << "eomgen: " << failure << "\n";
      return exit_user_error;
    }
    std::cerr << fmt::format("eomgen: wrote report.md, candidates.csv, error_vs_work.png{} to {}\n",
                             a.chosen ? ", chosen.csv and the chosen header" : "", directory);
  }
  if (a.interrupted) {
    std::cerr << fmt::format("eomgen: the scene was interrupted after {} runs: the report is partial\n", a.runs.size());
    return exit_numerical_failure;
  }
  if (!a.chosen) {
    std::cerr << "eomgen: no candidate reaches the scene's accuracy\n";
    return exit_numerical_failure;
  }
  return exit_success;
}

}  // namespace

Command add_scene_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("scene", "The cheapest model and integrator that answer a [scenes.NAME] to its accuracy");
  auto model = std::make_shared<std::string>(), name = std::make_shared<std::string>(), directory = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model, "Model file (TOML)")->required();
  cmd->add_option("NAME", *name, "The scene, a [scenes.NAME] of the model file")->required();
  cmd->add_option("-o,--output-dir", *directory, "Write report.md, candidates.csv, error_vs_work.png, chosen.csv and the "
                  "chosen model's header here");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, model, name, directory, format]() -> int {
    if (!cmd->parsed()) return -1;
    return scene(*model, *name, *directory, *format == "json");
  };
}

}  // namespace eomgen::cli
