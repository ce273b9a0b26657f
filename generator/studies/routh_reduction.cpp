#include "studies/routh_reduction.hpp"

#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::studies {

RouthRequest routh_request(const eomgen_model_abi& m, const std::vector<std::string>& at) {
  RouthRequest r;
  for (const std::string& text : at) {
    std::string name = text.substr(0, text.find('='));
    bool momentum = name.rfind("p_", 0) == 0 && state_index(m, name) < 0 &&
                    index_of(m.coordinate_names, m.num_coordinates, name.substr(2)) >= 0;
    if (momentum) {
      r.eliminated.push_back(name.substr(2));
      r.momentum_sets.push_back(text);
    } else {
      r.at.push_back(text);
    }
  }
  return r;
}

std::optional<int> load_reduced_problem(const std::string& model, const std::vector<std::string>& sets,
                                        const RouthRequest& request, LoadedProblem& out) {
  std::vector<std::string> all = sets;
  all.insert(all.end(), request.momentum_sets.begin(), request.momentum_sets.end());
  return load_problem(model, all, out, request.eliminated);
}

std::string routh_text(const Equations& e, const RouthRequest& request) {
  std::string out = "  Routh's reduction (Hiller §3.8.4): ";
  for (std::size_t i = 0; i < request.eliminated.size(); ++i)
    out += fmt::format("{}{} eliminated with {} held", i ? "; " : "", request.eliminated[i], request.momentum_sets[i]);
  out += "; the steady motion is an equilibrium of the reduced system\n";
  for (const NamedSymbolic& r : e.eliminated_coordinates)
    out += fmt::format("    der({}) = {}\n", r.name, canonical_text(r.expression));
  return out + fmt::format("    Routhian R = L - p*der(q) = {}\n", canonical_text(e.routhian));
}

std::string routh_json(const Equations& e, const RouthRequest& request) {
  std::string eliminated, held;
  for (std::size_t i = 0; i < request.eliminated.size(); ++i) {
    eliminated += (i ? ", " : "") + json_quoted(request.eliminated[i]);
    std::string set = request.momentum_sets[i];
    held += fmt::format("{}{}: {}", i ? ", " : "", json_quoted(set.substr(0, set.find('='))), set.substr(set.find('=') + 1));
  }
  return fmt::format(", \"routh\": {{\"eliminated\": [{}], \"momenta\": {{{}}}, \"routhian\": {}}}", eliminated, held,
                     json_quoted(canonical_text(e.routhian)));
}

}  // namespace eomgen::studies
