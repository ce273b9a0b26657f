/// @file `eomgen check-integral MODEL --action S.txt`: whether S(q, α, t) solves the
/// Hamilton–Jacobi equation of the model (Hiller §3.8.5). Exit 0 when it does, 1 when
/// it does not, 2 for mistakes in the model or in S.
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "symbolic_analysis/hamilton_jacobi.hpp"
#include "cli/commands.hpp"
#include "emit/formats.hpp"
#include "pipeline.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::cli {

namespace {

std::string verdict(const HamiltonJacobiCheck& c) {
  if (c.symbolic) return "holds: the residual simplifies to 0";
  if (c.holds())
    return fmt::format("holds at {} random points (largest |residual| {:.1e} of the size of its terms); GiNaC does "
                       "not bring the residual to 0 symbolically", c.points, c.largest_relative_residual);
  return "fails: " + c.failure;
}

void print_text(const Equations& e, const HamiltonJacobiCheck& c) {
  std::cout << fmt::format("{}: Hamilton–Jacobi equation dS/dt + H(q, dS/dq, t) = 0 (Hiller §3.8.5)\n", e.model_name);
  std::cout << fmt::format("  H = {}\n  S = {}\n", canonical_text(e.hamiltonian), canonical_text(c.action));
  std::string constants;
  for (const std::string& a : c.constants) constants += (constants.empty() ? "" : ", ") + a;
  std::cout << fmt::format("  constants of S: {}\n", constants.empty() ? "(none)" : constants);
  for (const NamedSymbolic& p : c.momenta) std::cout << fmt::format("  {} = dS/d{} = {}\n", p.name, p.name.substr(2), canonical_text(p.expression));
  std::cout << fmt::format("  dS/dt + H = {}\n  {}\n", canonical_text(c.residual), verdict(c));
}

void print_json(const Equations& e, const HamiltonJacobiCheck& c) {
  std::string constants, momenta;
  for (const std::string& a : c.constants) constants += (constants.empty() ? "" : ", ") + json_quoted(a);
  for (const NamedSymbolic& p : c.momenta)
    momenta += (momenta.empty() ? "" : ", ") + json_quoted(p.name) + ": " + json_quoted(canonical_text(p.expression));
  std::cout << fmt::format("{{\"model\": {}, \"hamiltonian\": {}, \"action\": {}, \"constants\": [{}], \"momenta\": {{{}}}, "
                           "\"residual\": {}, \"holds\": {}, \"symbolic\": {}, \"points\": {}, "
                           "\"largest_relative_residual\": {:.6g}, \"failure\": {}}}\n",
                           json_quoted(e.model_name), json_quoted(canonical_text(e.hamiltonian)),
                           json_quoted(canonical_text(c.action)), constants, momenta, json_quoted(canonical_text(c.residual)),
                           c.holds() ? "true" : "false", c.symbolic ? "true" : "false", c.points,
                           c.largest_relative_residual, c.holds() ? "null" : json_quoted(c.failure));
}

int check_integral(const std::string& model, const std::string& action_path, bool json) {
  std::ifstream in(action_path);
  if (!in) {
    std::cerr << fmt::format("eomgen: error: --action {}: cannot read the file\n", action_path);
    return exit_user_error;
  }
  std::stringstream text;
  text << in.rdbuf();
  Derivation d = derive_model_file_as(model, "hamilton");
  if (report_diagnostics(d.diagnostics, model)) return exit_user_error;
  Diagnostics diagnostics;
  auto check = check_hamilton_jacobi(*d.equations, text.str(), action_path, diagnostics);
  if (report_diagnostics(diagnostics, action_path)) return exit_user_error;
  json ? print_json(*d.equations, *check) : print_text(*d.equations, *check);
  return check->holds() ? exit_success : 1;
}

}  // namespace

Command add_check_integral_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("check-integral", "Check that S(q, alpha, t) solves the Hamilton–Jacobi equation "
                                                       "dS/dt + H(q, dS/dq, t) = 0 of a model (exit 0 if so, 1 if not)");
  auto model = std::make_shared<std::string>();
  auto action = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("MODEL", *model, "Model file (TOML); derived by Hamilton's method whatever it names")->required();
  cmd->add_option("--action", *action, "File with S as one expression in the coordinates, parameters, t and constants of "
                  "its own (any other name, e.g. alpha); # starts a comment")->required();
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, model, action, format]() -> int {
    if (!cmd->parsed()) return -1;
    return check_integral(*model, *action, *format == "json");
  };
}

}  // namespace eomgen::cli
