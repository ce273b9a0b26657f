#include <chrono>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "common/output_file.hpp"
#include "emit/cpp_header.hpp"
#include "pipeline.hpp"

namespace eomgen::cli {

int generate_header(const std::string& model_path, const std::string& directory, const std::string& header_file) {
  auto started = std::chrono::steady_clock::now();
  Derivation d = derive_model_file(model_path);
  if (report_diagnostics(d.diagnostics, model_path)) return exit_user_error;
  std::string text = emit_cpp_header(*d.equations);
  std::error_code ec;
  std::string path = !header_file.empty()
                         ? header_file
                         : (std::filesystem::path(directory) / (d.equations->model_name + ".hpp")).string();
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (std::string failure = write_file_atomically(path, text); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cerr << fmt::format("eomgen: generated {} ({} lines) in {:.3f} s\n", path,
                           std::count(text.begin(), text.end(), '\n'), seconds);
  return exit_success;
}

Command add_generate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("generate", "Write the model's self-contained C++ header (NAME.hpp)");
  auto model = std::make_shared<std::string>();
  auto directory = std::make_shared<std::string>(".");
  cmd->add_option("MODEL", *model, "Model file (TOML)")->required();
  auto header = std::make_shared<std::string>();
  auto* folder = cmd->add_option("-o,--output-dir", *directory, "Folder for NAME.hpp, NAME the model's name (default: the current folder)");
  cmd->add_option("--header", *header, "Write the header to exactly this file instead")->excludes(folder);
  return [cmd, model, directory, header]() -> int {
    if (!cmd->parsed()) return -1;
    return generate_header(*model, *directory, *header);
  };
}

}  // namespace eomgen::cli
