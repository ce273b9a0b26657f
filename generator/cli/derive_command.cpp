#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "common/output_file.hpp"
#include "emit/formats.hpp"
#include "pipeline.hpp"

namespace eomgen::cli {

int derive_and_write(const std::string& model_path, const std::string& format, const std::string& output,
                     bool linearize, const std::vector<std::string>& reduce, const std::string& variant,
                     bool written_out) {
  auto started = std::chrono::steady_clock::now();
  Derivation d = !reduce.empty() ? derive_reduced_model_file(model_path, reduce)
                                 : derive_model_file_for(model_path, {"", variant, {}, linearize || written_out});
  if (report_diagnostics(d.diagnostics, model_path)) return exit_user_error;
  if ((linearize || written_out) && !d.equations->intermediates.empty()) {
    std::cerr << (linearize ? "eomgen: error: --linearize differentiates equations written out in q; those of ball and "
                              "free joints hold the frames' quantities: use the generated header's linearization()\n"
                            : "eomgen: error: --written-out: a ball or free joint's quaternion is not written out in q; "
                              "its equations hold the frames' quantities: leave --written-out out\n");
    return exit_user_error;
  }
  if (linearize) add_linearization(*d.equations);
  std::string text = (*find_equation_format(format))(*d.equations);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (output.empty() || output == "-") {
    std::cout << text;
  } else if (std::string failure = write_file_atomically(output, text); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  // the equations are the same either way; the header's rhs solves them by the recursion or through M
  const char* form = !d.equations->articulated() ? "" : "; the header's rhs by the articulated-body recursion";
  std::cerr << fmt::format("eomgen: derived {} ({}, {} degree{} of freedom{}) in {:.3f} s\n", d.equations->model_name,
                           d.equations->method, d.equations->degrees_of_freedom,
                           d.equations->degrees_of_freedom == 1 ? "" : "s", form, seconds);
  return exit_success;
}

Command add_derive_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("derive", "Derive the equations of motion of a model file");
  auto model = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("text");
  auto output = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model, "Model file (TOML)")->required();
  cmd->add_option("--format", *format, "Output format: text (canonical, one equation per line), latex or json")
      ->check(CLI::IsMember(equation_format_names()));
  cmd->add_option("-o,--output", *output, "Write to this file instead of standard output (written only on success)");
  auto linearize = std::make_shared<bool>(false);
  cmd->add_flag("--linearize", *linearize, "Also print P = -df/dq', Q = -df/dq, B = df/du of M q'' + P q' + Q q = B u");
  auto reduce = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--reduce", *reduce, "Eliminate these cyclic coordinates by Routh's reduction, their momenta p_q "
                  "becoming parameters: --reduce phi")->delimiter(',');
  auto variant = std::make_shared<std::string>();
  cmd->add_option("--variant", *variant, "Derive the model's [variants.NAME] instead (parameters neglected or replaced, "
                  "coordinates frozen, small angles); the model is named MODEL_NAME");
  auto written_out = std::make_shared<bool>(false);
  cmd->add_flag("--written-out", *written_out,
                "Print the equations written out in q, as the symbolic analyses take them (and diff, for a tree of up "
                "to 4 velocities), where a tree of joints or a deep chain of frames would hold the recursion's "
                "quantities (not for ball or free joints)");
  return [cmd, model, format, output, linearize, reduce, variant, written_out]() -> int {
    if (!cmd->parsed()) return -1;
    return derive_and_write(*model, *format, *output, *linearize, *reduce, *variant, *written_out);
  };
}

}  // namespace eomgen::cli
