#include "symbolic_analysis/linear_closed_form.hpp"

namespace eomgen {

namespace {

// the system and its solution, or the reason either failed
std::string solve(const Equations& e, const std::vector<double>& parameters, const std::vector<double>& inputs,
                  const std::vector<double>& state, const std::vector<std::string>& outputs, bool keep_parameters,
                  LinearClosedForm& out) {
  out.system = exact_linear_system(e, parameters, inputs, state, keep_parameters, outputs);
  if (!out.system.refusal.empty()) return out.system.refusal;
  out.solution = closed_form_solution(out.system.A, out.system.B, out.system.C, out.system.D, out.system.parameter_values);
  return out.solution.refusal;
}

}  // namespace

LinearClosedForm linear_closed_form(const Equations& e, const std::vector<double>& parameters,
                                    const std::vector<double>& inputs, const std::vector<double>& state,
                                    const std::vector<std::string>& outputs) {
  LinearClosedForm out;
  out.parameter_refusal = solve(e, parameters, inputs, state, outputs, true, out);
  if (out.parameter_refusal.empty() || e.symbols.parameters.empty()) {
    out.refusal = out.parameter_refusal, out.parameter_refusal.clear();
    return out;
  }
  out.refusal = solve(e, parameters, inputs, state, outputs, false, out);
  return out;
}

}  // namespace eomgen
