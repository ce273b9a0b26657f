#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <tuple>
#include <variant>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "common/deadline.hpp"
#include "common/output_file.hpp"
#include "emit/cpp_header.hpp"
#include "emit/split_units.hpp"
#include "studies/scene_analysis.hpp"
#include "studies/split_output.hpp"
#include "pipeline.hpp"

namespace eomgen::cli {

namespace {

// the header of the model `eomgen scene` chooses for the scene, or the exit status
std::variant<std::pair<std::string, std::string>, int> scene_header(const std::string& model_path, const std::string& scene) {
  SceneAnalysis a = analyse_scene(model_path, scene, [](const std::string& line) { std::cerr << "eomgen: " << line << "\n"; });
  if (!a.refusal.empty()) {
    std::cerr << a.refusal << (a.refusal.back() == '\n' ? "" : "\n");
    return exit_user_error;
  }
  if (!a.chosen) {
    std::cerr << "eomgen: no candidate reaches the scene's accuracy; `eomgen scene` says which came closest\n";
    return exit_numerical_failure;
  }
  const SceneRun& run = a.runs[*a.chosen];
  const SceneCandidate& c = a.candidates[run.candidate];
  std::cerr << fmt::format("eomgen: scene {}: the {} model with {} ({}) meets the accuracy at the least work\n", scene, c.model,
                           run.integrator, run.setting);
  return std::pair{c.equations.model_name, c.header};
}

// NAME_split.hpp and the units of the header's large functions, next to the header
int write_split_units(const std::string& text, const std::string& name, const std::string& path, std::size_t min_kb) {
  std::filesystem::path header(path);
  std::string header_name = header.filename().string();
  std::vector<GeneratedFile> files = split_units(text, name, header_name, min_kb * 1024);
  if (std::string failure = write_split_files(header.parent_path().string(), name, header_name, files); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  if (files.empty()) {
    std::cerr << fmt::format("eomgen: --split: no function of {} has a body of {} KB or more; nothing to split "
                             "(a smaller --split-above splits more)\n", header_name, min_kb);
    return exit_success;
  }
  std::cerr << fmt::format("eomgen: split {} function(s) into their own translation units: include {} and compile", files.size() - 1,
                           files.front().name);
  for (std::size_t i = 1; i < files.size(); ++i) std::cerr << " " << files[i].name;
  std::cerr << "\n";
  return exit_success;
}

}  // namespace

int generate_header(const std::string& model_path, const std::string& directory, const std::string& header_file,
                    const std::string& variant, const std::string& scene, std::optional<std::size_t> split_above_kb,
                    ForwardDynamics forward_dynamics) {
  auto started = std::chrono::steady_clock::now();
  std::string text, name;
  if (!scene.empty()) {
    auto chosen = scene_header(model_path, scene);
    if (auto* status = std::get_if<int>(&chosen)) return *status;
    std::tie(name, text) = std::get<std::pair<std::string, std::string>>(chosen);
  } else {
    ModelChoice choice;
    choice.variant = variant, choice.forward_dynamics = forward_dynamics;
    Derivation d = derive_model_file_for(model_path, choice);
    if (report_diagnostics(d.diagnostics, model_path)) return exit_user_error;
    {
      DerivationDeadline writing(model_path, false);  // its progress only: the limits are the derivation's
      derivation_stage("the C++ header (common subexpressions, printing)");
      text = emit_cpp_header(*d.equations), name = d.equations->model_name;
    }
    derivation_stage("the header file");
  }
  std::error_code ec;
  std::string path = !header_file.empty()
                         ? header_file
                         : (std::filesystem::path(directory) / (name + ".hpp")).string();
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (std::string failure = write_file_atomically(path, text); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cerr << fmt::format("eomgen: generated {} ({} lines) in {:.3f} s\n", path,
                           std::count(text.begin(), text.end(), '\n'), seconds);
  return split_above_kb ? write_split_units(text, name, path, *split_above_kb) : exit_success;
}

Command add_generate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("generate", "Write the model's self-contained C++ header (NAME.hpp)");
  auto model = std::make_shared<std::string>();
  auto directory = std::make_shared<std::string>(".");
  cmd->add_option("MODEL", *model, "Model file (TOML)")->required();
  auto header = std::make_shared<std::string>();
  auto* folder = cmd->add_option("-o,--output-dir", *directory, "Folder for NAME.hpp, NAME the model's name (default: the current folder)");
  cmd->add_option("--header", *header, "Write the header to exactly this file instead")->excludes(folder);
  auto variant = std::make_shared<std::string>();
  auto* variant_option = cmd->add_option("--variant", *variant, "Generate the model's [variants.NAME] instead (header MODEL_NAME.hpp)");
  auto scene = std::make_shared<std::string>();
  cmd->add_option("--scene", *scene, "Generate the header of the cheapest model that answers [scenes.NAME] to its accuracy "
                  "(as `eomgen scene` chooses it)")->excludes(variant_option);
  auto split = std::make_shared<bool>(false);
  auto split_above = std::make_shared<std::size_t>(16);
  auto* split_flag = cmd->add_flag("--split", *split,
                                   "Also write NAME_split.hpp and NAME_<function>.cpp: each large function compiled once, for "
                                   "double, in its own translation unit (parallel builds; include NAME_split.hpp, link the units)");
  cmd->add_option("--split-above", *split_above, "With --split: the functions whose body has at least this many KB (default 16)")
      ->check(positive_number())
      ->needs(split_flag);
  auto form = std::make_shared<std::string>("chosen");
  cmd->add_option("--forward-dynamics", *form,
                  "How the rhs solves for q'': chosen (default: eomgen's choice, the articulated-body recursion for a "
                  "tree of particles of many coordinates or a deep tree of joints where its code is shorter, M = L D L^T "
                  "otherwise), "
                  "mass_matrix or articulated, to compare the two forms")
      ->check(CLI::IsMember({"chosen", "mass_matrix", "articulated"}))
      ->excludes("--scene");
  return [cmd, model, directory, header, variant, scene, split, split_above, form]() -> int {
    if (!cmd->parsed()) return -1;
    ForwardDynamics asked = *form == "mass_matrix"   ? ForwardDynamics::mass_matrix
                            : *form == "articulated" ? ForwardDynamics::articulated
                                                     : ForwardDynamics::chosen;
    return generate_header(*model, *directory, *header, *variant, *scene,
                           *split ? std::optional<std::size_t>(*split_above) : std::nullopt, asked);
  };
}

}  // namespace eomgen::cli
