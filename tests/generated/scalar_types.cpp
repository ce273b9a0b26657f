// A second translation unit that includes every generated header (so the test
// binary also checks that two units including the same header link) and
// instantiates every function with float, long double and an awkward scalar.
#include <algorithm>
#include <cmath>
#include <vector>

#include "all_generated_headers.hpp"
#include "generated/header_registry.hpp"
#include "support/awkward_scalar.hpp"
#include "support/scalar_agreement.hpp"

namespace eomgen::test {
namespace {

template <class T, class Array>
std::vector<T> shifted(const Array& values, double by) {
  std::vector<T> out;
  for (double v : values) out.push_back(T(v + by));
  out.push_back(T(0));  // never empty, so data() is valid for a model without inputs
  return out;
}

// every number a header's functions give at (near) the default state, in a fixed order
#define EOMGEN_EVERYTHING(NAME)                                                                      \
  template <class T>                                                                                 \
  std::vector<double> everything_##NAME() {                                                          \
    namespace m = eomgen::models::NAME;                                                              \
    constexpr std::size_t n = m::num_states, k = m::num_coordinates;                                 \
    std::vector<T> x = shifted<T>(m::default_state, 0.1), u = shifted<T>(m::default_inputs, 0.3);    \
    std::vector<T> p = shifted<T>(m::default_parameters, 0.0);                                       \
    std::vector<T> out(n + n * n + n * m::num_inputs + m::num_outputs + k * k + k + 2);              \
    T t(0.25);                                                                                       \
    T* o = out.data();                                                                               \
    m::rhs(t, x.data(), u.data(), p.data(), o);                                                      \
    m::jacobian_state(t, x.data(), u.data(), p.data(), o += n);                                      \
    m::jacobian_input(t, x.data(), u.data(), p.data(), o += n * n);                                  \
    m::outputs(t, x.data(), u.data(), p.data(), o += n * m::num_inputs);                             \
    m::mass_matrix(t, x.data(), p.data(), o += m::num_outputs);                                      \
    m::forcing(t, x.data(), u.data(), p.data(), o += k * k);                                         \
    o += k;                                                                                          \
    o[0] = m::kinetic_energy(t, x.data(), p.data());                                                 \
    o[1] = m::potential_energy(t, x.data(), p.data());                                               \
    m::Parameters<T> defaults;                                                                       \
    (void)defaults.values();                                                                         \
    std::vector<double> values;                                                                      \
    for (const T& v : out) values.push_back(to_double(v));                                           \
    return values;                                                                                   \
  }
EOMGEN_FOR_EACH_GENERATED_MODEL(EOMGEN_EVERYTHING)
#undef EOMGEN_EVERYTHING

}  // namespace

#define EOMGEN_AGREEMENT(NAME)                                                                  \
  {                                                                                             \
    std::vector<double> reference = everything_##NAME<double>();                                \
    result.push_back({#NAME, largest_difference(everything_##NAME<float>(), reference),         \
                      largest_difference(everything_##NAME<long double>(), reference),          \
                      largest_difference(everything_##NAME<awkward::Scalar>(), reference)});    \
  }

std::vector<ScalarAgreement> scalar_agreement() {
  std::vector<ScalarAgreement> result;
  EOMGEN_FOR_EACH_GENERATED_MODEL(EOMGEN_AGREEMENT)
  return result;
}

}  // namespace eomgen::test
