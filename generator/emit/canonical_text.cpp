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
// constraints, and for Appell's equations the pseudo-velocities and the acceleration energy
std::string constrained_text(const Equations& e) {
  std::string out;
  const ConstraintSet& c = e.constraints;
  if (c.size()) out += "\n# constraints C(q,t)*der(q) + b(q,t) = 0, the holonomic ones g(q,t) = 0 differentiated\n";
  for (unsigned i = 0; i < c.size(); ++i) {
    if (c.holonomic[i]) out += fmt::format("g[{}] = {}\n", c.names[i], canonical_text(c.position[i]));
    for (unsigned j = 0; j < c.jacobian.cols(); ++j)
      out += fmt::format("C[{}][{}] = {}\n", c.names[i], e.symbols.coordinate_names[j], canonical_text(c.jacobian(i, j)));
    out += fmt::format("b[{}] = {}\n", c.names[i], canonical_text(c.bias[i]));
  }
  if (e.has_multipliers) {
    out += "multipliers:";
    for (const std::string& name : c.names) out += " lambda_" + name;
    out += "\n";
  }
  if (!e.uses_pseudo_velocities()) return out;
  if (e.method == "hamilton") {
    out += "\n# generalized momenta p = dT/d der(q), the Hamiltonian H(q,p,t) and the canonical equations\n";
    for (const NamedSymbolic& p : e.pseudo_velocity_definitions) out += fmt::format("{} = {}\n", p.name, canonical_text(p.expression));
    if (const MomentumSolve* momentum = e.momentum()) {
      // M^-1 would swell: the generated code solves for der(q), and H and der(p) are written in der(q)
      out += "# H in mass-matrix form: der(q) solves Mp(q,t)*der(q) = p - bp(q,t); H and der(p) in q and der(q)\n";
      std::size_t n = momentum->bias.size();
      for (unsigned j = 0; j < n; ++j)
        for (unsigned k = 0; k < n; ++k) out += fmt::format("Mp[{}][{}] = {}\n", j, k, canonical_text(momentum->mass_matrix(j, k)));
      for (unsigned j = 0; j < n; ++j) out += fmt::format("bp[{}] = {}\n", j, canonical_text(momentum->bias[j]));
    }
    out += fmt::format("H = {}\n", canonical_text(e.hamiltonian));
    for (std::size_t j = 0; j < e.coordinate_rates.size() && !e.solves_for_velocities(); ++j)
      out += fmt::format("{} = {}\n", e.coordinate_velocities[j].get_name(), canonical_text(e.coordinate_rates[j]));
    for (std::size_t j = 0; j < e.forcing.size(); ++j)
      out += fmt::format("der({}) = {}\n", e.pseudo_velocity_definitions[j].name, canonical_text(e.forcing[j]));
    return out;
  }
  out += "\n# pseudo-velocities s = Y(q,t)*der(q) + y(q,t) and the kinematic equations\n";
  for (const NamedSymbolic& p : e.pseudo_velocity_definitions)
    out += fmt::format("s[{}] = {}\n", p.name, canonical_text(p.expression));
  for (std::size_t j = 0; j < e.coordinate_rates.size(); ++j)
    out += fmt::format("{} = {}\n", e.coordinate_velocities[j].get_name(), canonical_text(e.coordinate_rates[j]));
  if (!e.acceleration_energy_formed()) {
    out += "# M and f by the tree's recursions: Newton-Euler projected on the pseudo-velocities, as d S / d der(s) is\n";
    return out;
  }
  out += fmt::format("# acceleration energy (terms with der(s)); Appell: d S / d der(s) = Pi\nS = {}\n",
                     canonical_text(e.acceleration_energy));
  return out;
}

}  // namespace

std::string emit_canonical_text(const Equations& e) {
  const Symbols& s = e.symbols;
  const char* form = e.method == "hamilton"         ? "der(q) = dH/dp, der(p) = -dH/dq + Q (M = I, f = der(p))"
                     : e.uses_pseudo_velocities() ? "M(q,t)*der(s) = f(q,s,u,t), der(q) = W(q,t)*s + w(q,t)"
                     : e.has_multipliers        ? "M(q,t)*der(der(q)) = f(q,der(q),u,t) + C(q,t)^T*lambda"
                                                : "M(q,t)*der(der(q)) = f(q,der(q),u,t)";
  std::string out = fmt::format("# equations of motion by eomgen {}: {}; do not edit\n", version_string, form);
  out += fmt::format("model: {}\ntitle: {}\nmethod: {}\ntime: t\n", e.model_name, e.title, e.method);
  std::vector<std::string> velocities;
  for (const auto& v : s.velocities) velocities.push_back(v.get_name());
  out += fmt::format("coordinates: {}\nvelocities: {}\n", list(s.coordinate_names), list(velocities));
  std::string parameters = assignments(s.parameter_names, s.parameter_defaults);
  std::string inputs = assignments(s.input_names, s.input_defaults);
  out += fmt::format("parameters:{}{}\ninputs:{}{}\n", parameters.empty() ? "" : " ", parameters,
                     inputs.empty() ? "" : " ", inputs);
  out += fmt::format("degrees_of_freedom: {}\n\n", e.degrees_of_freedom);
  if (!e.intermediates.empty()) {
    out += "# recursive kinematics: the frames' and bodies' quantities used below, in order of computation\n";
    for (const Intermediate& i : e.intermediates)
      out += fmt::format("{} = {}\n", i.symbol.get_name(), canonical_text(i.definition));
    out += "\n";
  }
  std::size_t n = e.forcing.size();
  for (unsigned j = 0; j < n; ++j)
    for (unsigned k = 0; k < n; ++k) out += fmt::format("M[{}][{}] = {}\n", j, k, canonical_text(e.mass_matrix(j, k)));
  for (unsigned j = 0; j < n; ++j) out += fmt::format("f[{}] = {}\n", j, canonical_text(e.forcing[j]));
  out += fmt::format("T = {}\nV = {}\nR = {}\n", canonical_text(e.kinetic_energy), canonical_text(e.potential_energy),
                     canonical_text(e.dissipation));
  for (const NamedSymbolic& o : e.outputs) out += fmt::format("y[{}] = {}\n", o.name, canonical_text(o.expression));
  out += constrained_text(e);
  if (!e.eliminated_coordinates.empty()) {
    out += "\n# Routh's reduction: the cyclic coordinates' momenta held as parameters, R = L - p*der(q_cyclic)\n";
    for (const NamedSymbolic& r : e.eliminated_coordinates) out += fmt::format("der({}) = {}\n", r.name, canonical_text(r.expression));
    out += fmt::format("Routhian = {}\n", canonical_text(e.routhian));
  }
  if (!e.first_integrals.empty()) out += "\n# first integrals: constant along every motion\n";
  for (const FirstIntegral& f : e.first_integrals)
    out += fmt::format("# {}\nI[{}] = {}\n", f.reason, f.name, canonical_text(f.expression));
  if (e.has_linearization) {
    out += "\n# linearization M q'' + P q' + Q q = B u about a state with q'' = 0\n";
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        out += fmt::format("P[{}][{}] = {}\n", j, k, canonical_text(e.linear_damping_gyroscopic(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < e.linear_stiffness_circulatory.cols(); ++k)
        out += fmt::format("Q[{}][{}] = {}\n", j, k, canonical_text(e.linear_stiffness_circulatory(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < e.symbols.inputs.size(); ++k)
        out += fmt::format("B[{}][{}] = {}\n", j, k, canonical_text(e.linear_input(j, k)));
  }
  return out;
}

}  // namespace eomgen
