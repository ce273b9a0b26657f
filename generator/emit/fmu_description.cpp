#include "emit/fmu_description.hpp"
#include "emit/formats.hpp"

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include <fmt/format.h>


namespace eomgen {

namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::uint64_t fnv1a(const std::string& text, std::uint64_t h) {
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

// the variables in value-reference order; a derivative that is itself a state (q' = v in
// Lagrange's equations, named der(q) either way) is that state's variable, not a second one
struct Variables {
  std::vector<std::string> lines;
  std::vector<int> index_of_reference;  // 1-based ScalarVariable index, 0 where no variable stands
};


}  // namespace

std::string fmu_guid(const std::string& header_text) {
  std::uint64_t a = fnv1a(header_text, 1469598103934665603ull), b = fnv1a(header_text, a ^ 0x9e3779b97f4a7c15ull);
  return fmt::format("{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}", a >> 32, (a >> 16) & 0xffff, a & 0xffff, b >> 48,
                     b & 0xffffffffffffull);
}

std::string fmi2_model_description(const Equations& e, const std::string& guid, FmuKinds kinds, const std::string& version,
                                   const std::vector<double>& nominals) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), k = e.num_velocities(), S = n + k, P = s.parameters.size(), U = s.inputs.size(),
              Y = e.outputs.size();
  std::vector<std::string> states = s.coordinate_names;
  for (const auto& v : s.velocities) states.push_back(v.get_name());
  std::vector<double> start = s.initial_coordinates;
  start.insert(start.end(), s.initial_velocities.begin(), s.initial_velocities.end());
  // Lagrange's q' = v: the derivative of q_i is the state der(q_i)
  bool kinematic = !e.uses_pseudo_velocities() && e.hamiltonian.is_zero();
  Variables vars;
  vars.index_of_reference.assign(2 * S + P + U + Y, 0);
  auto add = [&](std::size_t reference, const std::string& line) {
    vars.lines.push_back(line);
    vars.index_of_reference[reference] = int(vars.lines.size());
  };
  for (std::size_t i = 0; i < S; ++i) {
    std::string derivative = kinematic && i >= n ? fmt::format(" derivative=\"{}\"", i - n + 1) : "";
    if (i < nominals.size() && std::isfinite(nominals[i]) && nominals[i] > 0)
      derivative += fmt::format(" nominal=\"{:.3g}\"", nominals[i]);
    add(i, fmt::format("    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"local\" variability=\"continuous\" "
                       "initial=\"exact\">\n      <Real start=\"{}\"{}/>\n    </ScalarVariable>",
                       xml_escaped(states[i]), i, format_number(start[i]), derivative));
  }
  for (std::size_t i = 0; i < S; ++i) {
    if (kinematic && i < n) {
      vars.index_of_reference[S + i] = vars.index_of_reference[n + i];
      continue;
    }
    add(S + i, fmt::format("    <ScalarVariable name=\"der({})\" valueReference=\"{}\" causality=\"local\" "
                           "variability=\"continuous\" initial=\"calculated\">\n      <Real derivative=\"{}\"/>\n"
                           "    </ScalarVariable>",
                           xml_escaped(states[i]), S + i, vars.index_of_reference[i]));
  }
  for (std::size_t i = 0; i < P; ++i)
    add(2 * S + i, fmt::format("    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"parameter\" variability=\"fixed\" "
                               "initial=\"exact\">\n      <Real start=\"{}\"/>\n    </ScalarVariable>",
                               xml_escaped(s.parameter_names[i]), 2 * S + i, format_number(s.parameter_defaults[i])));
  for (std::size_t i = 0; i < U; ++i)
    add(2 * S + P + i, fmt::format("    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"input\" "
                                   "variability=\"continuous\">\n      <Real start=\"{}\"/>\n    </ScalarVariable>",
                                   xml_escaped(s.input_names[i]), 2 * S + P + i, format_number(s.input_defaults[i])));
  for (std::size_t i = 0; i < Y; ++i)
    add(2 * S + P + U + i, fmt::format("    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"output\" "
                                       "variability=\"continuous\" initial=\"calculated\">\n      <Real/>\n    </ScalarVariable>",
                                       xml_escaped(e.outputs[i].name), 2 * S + P + U + i));

  // which states and inputs an expression contains, as ScalarVariable indices
  auto dependencies = [&](const std::vector<GiNaC::ex>& parts) {
    std::set<int> found;
    for (const GiNaC::ex& x : parts) {
      for (std::size_t i = 0; i < n; ++i)
        if (x.has(s.coordinates[i])) found.insert(vars.index_of_reference[i]);
      for (std::size_t i = 0; i < k; ++i)
        if (x.has(s.velocities[i])) found.insert(vars.index_of_reference[n + i]);
      for (std::size_t i = 0; i < U; ++i)
        if (x.has(s.inputs[i])) found.insert(vars.index_of_reference[2 * S + P + i]);
    }
    std::string out;
    for (int i : found) out += (out.empty() ? "" : " ") + std::to_string(i);
    return out;
  };
  // the velocities' derivatives M⁻¹ f: a row depends on what every row M couples it to contains
  std::vector<std::size_t> block(k);
  for (std::size_t i = 0; i < k; ++i) block[i] = i;
  for (bool merged = true; merged;) {
    merged = false;
    for (unsigned i = 0; i < k; ++i)
      for (unsigned j = 0; j < k; ++j)
        if (block[i] != block[j] && !e.mass_matrix(i, j).is_zero()) {
          std::size_t from = std::max(block[i], block[j]), to = std::min(block[i], block[j]);
          for (std::size_t& b : block)
            if (b == from) b = to;
          merged = true;
        }
  }
  std::string derivatives;
  for (std::size_t i = 0; i < S; ++i) {
    std::vector<GiNaC::ex> parts;
    if (i < n) parts.push_back(kinematic ? GiNaC::ex(s.velocities[i]) : e.coordinate_rates.empty() ? GiNaC::ex(s.velocities[i]) : e.coordinate_rates[i]);
    else
      for (unsigned r = 0; r < k; ++r)
        if (block[r] == block[i - n]) {
          parts.push_back(e.forcing[r]);
          for (unsigned c = 0; c < k; ++c) parts.push_back(e.mass_matrix(r, c));
        }
    bool all = i < n && e.solves_for_velocities();
    derivatives += fmt::format("      <Unknown index=\"{}\"{}/>\n", vars.index_of_reference[S + i],
                               all ? "" : fmt::format(" dependencies=\"{}\"", dependencies(parts)));
  }
  std::string outputs;
  for (std::size_t i = 0; i < Y; ++i)
    outputs += fmt::format("      <Unknown index=\"{}\" dependencies=\"{}\"/>\n", vars.index_of_reference[2 * S + P + U + i],
                           dependencies({e.outputs[i].expression}));
  std::string initial;  // the calculated variables at initialization: the derivatives and the outputs
  std::set<int> listed;
  for (std::size_t i = 0; i < S; ++i)
    if (vars.index_of_reference[S + i] != vars.index_of_reference[i] && !(kinematic && i < n))
      listed.insert(vars.index_of_reference[S + i]);
  for (std::size_t i = 0; i < Y; ++i) listed.insert(vars.index_of_reference[2 * S + P + U + i]);
  for (int i : listed) initial += fmt::format("      <Unknown index=\"{}\"/>\n", i);

  std::string body;
  for (const std::string& line : vars.lines) body += line + "\n";
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"{0}\" guid=\"{1}\" description=\"{2}\" "
      "generationTool=\"eomgen {3}\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n"
      "{4}{5}"
      "  <DefaultExperiment startTime=\"0\" stopTime=\"10\" tolerance=\"1e-08\"/>\n"
      "  <ModelVariables>\n{6}  </ModelVariables>\n"
      "  <ModelStructure>\n{7}    <Derivatives>\n{8}    </Derivatives>\n{9}  </ModelStructure>\n"
      "</fmiModelDescription>\n",
      e.model_name, guid, xml_escaped(e.title), version,
      kinds.model_exchange
          ? fmt::format("  <ModelExchange modelIdentifier=\"{}\" providesDirectionalDerivative=\"true\"/>\n", e.model_name)
          : "",
      kinds.co_simulation ? fmt::format("  <CoSimulation modelIdentifier=\"{}\" canHandleVariableCommunicationStepSize=\"true\" "
                                        "providesDirectionalDerivative=\"true\"/>\n",
                                        e.model_name)
                          : "",
      body, outputs.empty() ? "" : "    <Outputs>\n" + outputs + "    </Outputs>\n", derivatives,
      initial.empty() ? "" : "    <InitialUnknowns>\n" + initial + "    </InitialUnknowns>\n");
}

}  // namespace eomgen
