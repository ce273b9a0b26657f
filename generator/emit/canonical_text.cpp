#include <fmt/format.h>

#include "common/version.hpp"
#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen {

namespace {
std::string list(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string assignments(const std::vector<std::string>& names, const std::vector<double>& values) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (s.empty() ? "" : ", ") + names[i] + " = " + format_number(values[i]);
  return s;
}
}  // namespace

std::string emit_canonical_text(const Equations& e) {
  const Symbols& s = e.symbols;
  std::string out = fmt::format("# equations of motion by eomgen {}: M(q,t)*der(der(q)) = f(q,der(q),u,t); do not edit\n",
                                version_string);
  out += fmt::format("model: {}\ntitle: {}\nmethod: {}\ntime: t\n", e.model_name, e.title, e.method);
  std::vector<std::string> velocities;
  for (const auto& v : s.velocities) velocities.push_back(v.get_name());
  out += fmt::format("coordinates: {}\nvelocities: {}\n", list(s.coordinate_names), list(velocities));
  std::string parameters = assignments(s.parameter_names, s.parameter_defaults);
  std::string inputs = assignments(s.input_names, s.input_defaults);
  out += fmt::format("parameters:{}{}\ninputs:{}{}\n", parameters.empty() ? "" : " ", parameters,
                     inputs.empty() ? "" : " ", inputs);
  out += fmt::format("degrees_of_freedom: {}\n\n", e.degrees_of_freedom);
  std::size_t n = e.forcing.size();
  for (unsigned j = 0; j < n; ++j)
    for (unsigned k = 0; k < n; ++k) out += fmt::format("M[{}][{}] = {}\n", j, k, canonical_text(e.mass_matrix(j, k)));
  for (unsigned j = 0; j < n; ++j) out += fmt::format("f[{}] = {}\n", j, canonical_text(e.forcing[j]));
  out += fmt::format("T = {}\nV = {}\nR = {}\n", canonical_text(e.kinetic_energy), canonical_text(e.potential_energy),
                     canonical_text(e.dissipation));
  for (const NamedSymbolic& o : e.outputs) out += fmt::format("y[{}] = {}\n", o.name, canonical_text(o.expression));
  if (e.has_linearization) {
    out += "\n# linearization M q'' + P q' + Q q = B u about a state with q'' = 0\n";
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        out += fmt::format("P[{}][{}] = {}\n", j, k, canonical_text(e.linear_damping_gyroscopic(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        out += fmt::format("Q[{}][{}] = {}\n", j, k, canonical_text(e.linear_stiffness_circulatory(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < e.symbols.inputs.size(); ++k)
        out += fmt::format("B[{}][{}] = {}\n", j, k, canonical_text(e.linear_input(j, k)));
  }
  return out;
}

}  // namespace eomgen
