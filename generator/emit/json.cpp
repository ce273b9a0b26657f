#include <fmt/format.h>

#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen {

namespace {

std::string quote(const std::string& s) { return json_quoted(s); }

std::string expression(const GiNaC::ex& e) { return quote(canonical_text(e)); }

std::string string_array(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + quote(x);
  return "[" + s + "]";
}

std::string number_object(const std::vector<std::string>& names, const std::vector<double>& values) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (s.empty() ? "" : ", ") + quote(names[i]) + ": " + format_number(values[i]);
  return "{" + s + "}";
}

std::string expression_array(const std::vector<GiNaC::ex>& v) {
  std::string s;
  for (const GiNaC::ex& x : v) s += (s.empty() ? "" : ", ") + expression(x);
  return "[" + s + "]";
}

// "momenta", "hamiltonian" and "canonical_equations" of Hamilton's equations; the kinematic
// equations also as "coordinate_rates" and the momenta's definitions as "pseudo_velocities",
// so that readers of Appell's form read these too
std::string hamilton_json(const Equations& e) {
  std::string momenta, rates, forces;
  for (const NamedSymbolic& p : e.pseudo_velocity_definitions)
    momenta += (momenta.empty() ? "" : ", ") + quote(p.name) + ": " + expression(p.expression);
  for (std::size_t j = 0; j < e.coordinate_rates.size(); ++j) {
    rates += (rates.empty() ? "" : ", ") + quote(e.coordinate_velocities[j].get_name()) + ": " + expression(e.coordinate_rates[j]);
    forces += (forces.empty() ? "" : ", ") + quote("der(" + e.pseudo_velocity_definitions[j].name + ")") + ": " +
              expression(e.forcing[j]);
  }
  std::string form = ",\n  \"hamiltonian_form\": \"closed\"";
  if (const MomentumSolve* momentum = e.momentum()) {
    // der(q) solves momentum_mass_matrix*der(q) = p - momentum_bias; H and der(p) are in q and der(q)
    std::string rows;
    for (unsigned j = 0; j < momentum->bias.size(); ++j) {
      std::vector<GiNaC::ex> row;
      for (unsigned k = 0; k < momentum->bias.size(); ++k) row.push_back(momentum->mass_matrix(j, k));
      rows += (j ? ", " : "") + expression_array(row);
    }
    form = ",\n  \"hamiltonian_form\": \"mass_matrix\",\n  \"momentum_mass_matrix\": [" + rows +
           "],\n  \"momentum_bias\": " + expression_array(momentum->bias);
  }
  return form + ",\n  \"momenta\": {" + momenta + "}" + ",\n  \"hamiltonian\": " + expression(e.hamiltonian) +
         ",\n  \"canonical_equations\": {" + rates + ", " + forces + "}" + ",\n  \"pseudo_velocities\": {" + momenta + "}" +
         ",\n  \"coordinate_rates\": " + expression_array(e.coordinate_rates);
}

// "constraints" (every model that has them), "multipliers" (Lagrange I), and for
// Appell's equations "pseudo_velocities", "coordinate_rates" and "acceleration_energy"
std::string constrained_json(const Equations& e) {
  const ConstraintSet& c = e.constraints;
  std::string out;
  if (c.size()) {
    out += ",\n  \"constraints\": [";
    for (unsigned i = 0; i < c.size(); ++i) {
      std::vector<GiNaC::ex> row;
      for (unsigned j = 0; j < c.jacobian.cols(); ++j) row.push_back(c.jacobian(i, j));
      out += fmt::format("{}\n    {{\"name\": {}, \"holonomic\": {}, \"position\": {}, \"jacobian\": {}, \"bias\": {}}}",
                         i ? "," : "", quote(c.names[i]), c.holonomic[i] ? "true" : "false",
                         c.holonomic[i] ? expression(c.position[i]) : "null", expression_array(row),
                         expression(c.bias[i]));
    }
    out += "\n  ]";
  }
  if (e.has_multipliers) {
    std::vector<std::string> names;
    for (const std::string& n : c.names) names.push_back("lambda_" + n);
    out += ",\n  \"multipliers\": " + string_array(names);
  }
  if (!e.uses_pseudo_velocities()) return out;
  if (e.method == "hamilton") return out + hamilton_json(e);
  std::string definitions;
  for (const NamedSymbolic& p : e.pseudo_velocity_definitions)
    definitions += (definitions.empty() ? "" : ", ") + quote(p.name) + ": " + expression(p.expression);
  out += ",\n  \"pseudo_velocities\": {" + definitions + "}";
  out += ",\n  \"coordinate_rates\": " + expression_array(e.coordinate_rates);
  out += ",\n  \"acceleration_energy\": " + (e.acceleration_energy_formed() ? expression(e.acceleration_energy) : "null");
  return out;
}

}  // namespace

std::string json_quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<int>(c));
        else out += c;
    }
  }
  return out + "\"";
}

std::string emit_json(const Equations& e) {
  const Symbols& s = e.symbols;
  std::size_t n = e.forcing.size();
  std::vector<std::string> velocities;
  for (const auto& v : s.velocities) velocities.push_back(v.get_name());
  std::string out = "{\n";
  out += fmt::format("  \"model\": {},\n  \"title\": {},\n  \"method\": {},\n  \"time\": \"t\",\n", quote(e.model_name),
                     quote(e.title), quote(e.method));
  out += fmt::format("  \"coordinates\": {},\n  \"velocities\": {},\n", string_array(s.coordinate_names),
                     string_array(velocities));
  out += fmt::format("  \"parameters\": {},\n  \"inputs\": {},\n", number_object(s.parameter_names, s.parameter_defaults),
                     number_object(s.input_names, s.input_defaults));
  if (!e.intermediates.empty()) {
    // recursive kinematics: what the symbols below stand for, in order of computation
    out += "  \"intermediates\": [";
    for (std::size_t i = 0; i < e.intermediates.size(); ++i)
      out += fmt::format("{}\n    {{\"name\": {}, \"definition\": {}}}", i ? "," : "",
                         quote(e.intermediates[i].symbol.get_name()), expression(e.intermediates[i].definition));
    out += "\n  ],\n";
  }
  out += fmt::format("  \"degrees_of_freedom\": {},\n  \"mass_matrix\": [", e.degrees_of_freedom);
  for (unsigned j = 0; j < n; ++j) {
    out += j ? ",\n    [" : "\n    [";
    for (unsigned k = 0; k < n; ++k) out += (k ? ", " : "") + expression(e.mass_matrix(j, k));
    out += "]";
  }
  out += "\n  ],\n  \"forcing\": [";
  for (unsigned j = 0; j < n; ++j) out += (j ? ",\n    " : "\n    ") + expression(e.forcing[j]);
  out += "\n  ],\n";
  out += fmt::format("  \"kinetic_energy\": {},\n  \"potential_energy\": {},\n  \"dissipation\": {},\n",
                     expression(e.kinetic_energy), expression(e.potential_energy), expression(e.dissipation));
  std::string outputs;
  for (const NamedSymbolic& o : e.outputs) outputs += (outputs.empty() ? "" : ", ") + quote(o.name) + ": " + expression(o.expression);
  out += "  \"outputs\": {" + outputs + "}";
  out += constrained_json(e);
  if (!e.eliminated_coordinates.empty()) {
    std::string rates;
    for (const NamedSymbolic& r : e.eliminated_coordinates)
      rates += (rates.empty() ? "" : ", ") + quote("der(" + r.name + ")") + ": " + expression(r.expression);
    out += ",\n  \"routh\": {\"eliminated\": {" + rates + "}, \"routhian\": " + expression(e.routhian) + "}";
  }
  out += ",\n  \"first_integrals\": [";
  for (std::size_t i = 0; i < e.first_integrals.size(); ++i) {
    const FirstIntegral& f = e.first_integrals[i];
    out += fmt::format("{}\n    {{\"name\": {}, \"expression\": {}, \"reason\": {}}}", i ? "," : "", quote(f.name),
                       expression(f.expression), quote(f.reason));
  }
  out += e.first_integrals.empty() ? "]" : "\n  ]";
  if (e.has_linearization) {
    auto matrix = [&](const GiNaC::matrix& A, std::size_t rows, std::size_t cols) {
      std::string m = "[";
      for (unsigned j = 0; j < rows; ++j) {
        m += j ? ", [" : "[";
        for (unsigned k = 0; k < cols; ++k) m += (k ? ", " : "") + expression(A(j, k));
        m += "]";
      }
      return m + "]";
    };
    out += fmt::format(",\n  \"linearization\": {{\"P\": {}, \"Q\": {}, \"B\": {}}}",
                       matrix(e.linear_damping_gyroscopic, n, n), matrix(e.linear_stiffness_circulatory, n, e.linear_stiffness_circulatory.cols()),
                       matrix(e.linear_input, n, s.inputs.size()));
  }
  out += "\n}\n";
  return out;
}

}  // namespace eomgen
