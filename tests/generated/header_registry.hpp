/// @file Every header in generated/, compiled into the test binary and
/// reachable by model name, for the accuracy and instantiation tests.
#pragma once

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "model_abi.h"

namespace eomgen::test {

template <class T>
using StateFunction = std::function<void(T, const T*, const T*, const T*, T*)>;
template <class T>
using EnergyFunction = std::function<T(T, const T*, const T*)>;

struct GeneratedModel {
  std::string name;
  std::size_t num_coordinates, num_states, num_parameters, num_inputs, num_outputs;
  std::vector<double> default_parameters, default_state, default_inputs;
  std::function<void(double, const double*, const double*, double*)> mass_matrix;
  StateFunction<double> forcing, rhs, jacobian_state, jacobian_input, outputs;
  EnergyFunction<double> kinetic_energy, potential_energy;
  StateFunction<std::complex<double>> rhs_complex, jacobian_state_complex;
  const eomgen_model_abi* abi;  // the same functions through the C interface the runtime uses
};

/// The compiled-in model of this name (fails the test when there is none).
const GeneratedModel& generated_model(const std::string& name);

std::vector<GeneratedModel> generated_models();

/// Runs every function of every header with float, long double and an awkward
/// scalar type at the default state; returns the largest relative difference
/// from double for each type, by model (defined in a second translation unit).
struct ScalarAgreement {
  std::string model;
  double float_error, long_double_error, awkward_error;
};
std::vector<ScalarAgreement> scalar_agreement();

}  // namespace eomgen::test
