#include "generated/header_registry.hpp"

#include "all_generated_headers.hpp"
#include "model_abi.h"

#define EOMGEN_DEFINE_ABI(NAME) EOMGEN_MODEL_FUNCTION(abi_of_##NAME, NAME)
EOMGEN_FOR_EACH_GENERATED_MODEL(EOMGEN_DEFINE_ABI)
#undef EOMGEN_DEFINE_ABI

namespace eomgen::test {

namespace {
template <class T>
std::vector<double> list(const T& array) {
  return std::vector<double>(array.begin(), array.end());
}
}  // namespace

#define EOMGEN_REGISTER(NAME)                                                                                  \
  {                                                                                                            \
    namespace m = eomgen::models::NAME;                                                                        \
    using cd = std::complex<double>;                                                                           \
    models.push_back({#NAME, m::num_coordinates, m::num_states, m::num_parameters, m::num_inputs,             \
                      m::num_outputs, list(m::default_parameters), list(m::default_state),                     \
                      list(m::default_inputs), m::mass_matrix<double>, m::forcing<double>, m::rhs<double>,     \
                      m::jacobian_state<double>, m::jacobian_input<double>, m::outputs<double>,               \
                      m::kinetic_energy<double>, m::potential_energy<double>, m::rhs<cd>,                      \
                      m::jacobian_state<cd>, abi_of_##NAME()});                                                \
  }

std::vector<GeneratedModel> generated_models() {
  std::vector<GeneratedModel> models;
  EOMGEN_FOR_EACH_GENERATED_MODEL(EOMGEN_REGISTER)
  return models;
}

const GeneratedModel& generated_model(const std::string& name) {
  static const std::vector<GeneratedModel> models = generated_models();
  for (const GeneratedModel& m : models)
    if (m.name == name) return m;
  throw std::runtime_error("no generated header for " + name);
}

}  // namespace eomgen::test
