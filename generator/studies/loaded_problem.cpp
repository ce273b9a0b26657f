#include "studies/loaded_problem.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "derive/initial_state.hpp"
#include "emit/cpp_header.hpp"
#include "symbolic/constant_value.hpp"

namespace eomgen::studies {

bool parse_assignments(const std::vector<std::string>& texts, const char* flag, std::vector<Assignment>& out) {
  for (const std::string& text : texts) {
    std::size_t eq = text.find('=');
    std::optional<double> value = eq == std::string::npos ? std::nullopt : constant_value(text.substr(eq + 1));
    if (eq == std::string::npos || eq == 0 || !value) {
      std::cerr << fmt::format("eomgen: error: {} '{}': expected NAME=NUMBER or a constant expression, e.g. {} m=2.5 or "
                               "{} theta=3*Pi/4\n", flag, text, flag, flag);
      return false;
    }
    out.push_back({text.substr(0, eq), *value});
  }
  return true;
}

int index_of(const char* const* names, std::size_t count, const std::string& name) {
  for (std::size_t i = 0; i < count; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

int state_index(const eomgen_model_abi& m, const std::string& name) {
  if (int i = index_of(m.state_names, m.num_states, name); i >= 0) return i;
  // der(q) names a pseudo-velocity that is defined as der(q)
  for (std::size_t i = 0; i < m.num_velocities; ++i)
    if (name == m.velocity_definitions[i]) return static_cast<int>(m.num_coordinates + i);
  return -1;
}

bool assign_states(const eomgen_model_abi& m, const std::vector<std::string>& texts, const char* flag,
                   std::vector<double>& x, std::vector<bool>* assigned) {
  if (assigned) assigned->assign(m.num_states, false);
  std::vector<Assignment> assignments;
  if (!parse_assignments(texts, flag, assignments)) return false;
  std::vector<std::string> states(m.state_names, m.state_names + m.num_states);
  for (const Assignment& a : assignments) {
    int i = state_index(m, a.name);
    if (i >= 0) {
      x[static_cast<std::size_t>(i)] = a.value;
      if (assigned) (*assigned)[static_cast<std::size_t>(i)] = true;
      continue;
    }
    bool rate = a.name.rfind("der(", 0) == 0 && index_of(m.coordinate_names, m.num_coordinates, a.name.substr(4, a.name.size() - 5)) >= 0;
    if (rate && m.num_velocities != m.num_coordinates)
      std::cerr << fmt::format("eomgen: error: {} {}: the state of this Appell model holds the pseudo-velocities, and "
                               "{} follows from them and the constraints; {}\n", flag, a.name, a.name,
                               suggest(a.name, states, "states"));
    else
      std::cerr << fmt::format("eomgen: error: {} {}: not a coordinate or a velocity of the state; {}\n", flag, a.name,
                               suggest(a.name, states, "states"));
    return false;
  }
  return true;
}

std::optional<int> load_problem(const std::string& model, const std::vector<std::string>& sets, LoadedProblem& out,
                                const std::vector<std::string>& reduce, const ModelChoice& choice) {
  Derivation d = !reduce.empty() ? derive_reduced_model_file(model, reduce) : derive_model_file_for(model, choice);
  if (!d.diagnostics.empty()) {
    std::cerr << d.diagnostics.format();
    return exit_user_error;
  }
  return load_equations(*d.equations, sets, out);
}

std::optional<int> load_equations(const Equations& equations, const std::vector<std::string>& sets, LoadedProblem& out) {
  const std::string& model = equations.source;
  out.equations = equations;
  out.header = emit_cpp_header(out.equations);
  std::string error;
  bool compiler_missing = false;
  out.compiled = runtime::load_compiled_model(out.header, out.equations.model_name, error, &compiler_missing);
  if (!out.compiled) {
    std::cerr << (compiler_missing ? "eomgen: error: " : "eomgen: internal error: ") << error << "\n";
    return compiler_missing ? exit_user_error : exit_internal_error;
  }
  const eomgen_model_abi& m = *out.compiled->abi();
  out.problem = runtime::Problem{};
  out.problem.model = &m;
  out.problem.parameters.assign(m.default_parameters, m.default_parameters + m.num_parameters);
  out.problem.inputs.assign(m.default_inputs, m.default_inputs + m.num_inputs);
  out.problem.reference = out.compiled->reference;
  std::vector<Assignment> assignments;
  if (!parse_assignments(sets, "--set", assignments)) return exit_user_error;
  for (const Assignment& a : assignments) {
    if (int i = index_of(m.parameter_names, m.num_parameters, a.name); i >= 0) out.problem.parameters[i] = a.value;
    else if (int k = index_of(m.input_names, m.num_inputs, a.name); k >= 0) out.problem.inputs[k] = a.value;
    else {
      std::vector<std::string> all(m.parameter_names, m.parameter_names + m.num_parameters);
      all.insert(all.end(), m.input_names, m.input_names + m.num_inputs);
      std::cerr << fmt::format("eomgen: error: --set {}: no parameter or input of that name; {}\n", a.name,
                               suggest(a.name, all, "names"));
      return exit_user_error;
    }
  }
  std::string failed;
  auto x0 = initial_state(out.equations, out.problem.parameters, failed);
  if (!x0) {
    std::cerr << fmt::format("eomgen: error: {} is not a finite real number with these parameter values\n  hint: check "
                             "the --set values against the expression in {}\n", failed, model);
    return exit_user_error;
  }
  out.initial_state = *x0;
  return std::nullopt;
}

}  // namespace eomgen::studies
