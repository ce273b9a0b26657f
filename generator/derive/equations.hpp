/// @file The derived equations of motion M(q,t)·q̈ = f(q,q̇,u,t), with what
/// the output formats need to name things; the plain result of every method.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

struct Equations {
  std::string model_name, title, method;
  std::string source;  // the model file's path as given
  Symbols symbols;
  std::size_t degrees_of_freedom = 0;
  GiNaC::matrix mass_matrix;           // n × n, symmetric
  std::vector<GiNaC::ex> forcing;      // n
  GiNaC::ex kinetic_energy, potential_energy, dissipation;
  std::vector<NamedSymbolic> outputs;
  /// T + V is a first integral when the inputs are zero: no dissipation, no applied
  /// forces at u = 0, and no explicit time dependence (Hiller §3.6).
  bool conserves_energy_without_inputs = false;
  /// Linearization M q'' + P q' + Q q = B u about states with q'' = 0 (Hiller §5.3),
  /// in the coordinates and velocities of the state: filled by add_linearization().
  bool has_linearization = false;
  GiNaC::matrix linear_damping_gyroscopic, linear_stiffness_circulatory, linear_input;  // P, Q, B
};

/// P = −∂f/∂q', Q = −∂f/∂q, B = ∂f/∂u, each entry kept compact.
void add_linearization(Equations& equations);

/// Coordinates on which neither the mass matrix nor the forcing depends (Hiller §3.8).
std::vector<bool> cyclic_coordinates(const Equations& equations);

}  // namespace eomgen
