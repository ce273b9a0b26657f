// The entry points of <eomgen/runtime.hpp> that the other runtime files do not already provide.
#include "eomgen/runtime.hpp"

namespace eomgen::runtime {

Problem default_problem(const eomgen_model_abi& model) {
  Problem p;
  p.model = &model;
  p.parameters.assign(model.default_parameters, model.default_parameters + model.num_parameters);
  p.inputs.assign(model.default_inputs, model.default_inputs + model.num_inputs);
  return p;
}

std::vector<double> default_state(const eomgen_model_abi& model) {
  return {model.default_state, model.default_state + model.num_states};
}

std::vector<double> first_integrals_at(const Problem& problem, double t, const std::vector<double>& x) {
  std::vector<double> out(problem.model->num_first_integrals);
  if (!out.empty()) problem.model->first_integrals(t, x.data(), problem.parameters.data(), out.data());
  return out;
}

}  // namespace eomgen::runtime
