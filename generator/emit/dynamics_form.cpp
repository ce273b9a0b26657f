#include "emit/dynamics_form.hpp"

namespace eomgen {

DynamicsForm dynamics_form(const Equations& e) {
  if (e.solves_for_velocities()) return DynamicsForm::momentum;
  if (e.articulated) return DynamicsForm::particle_tree;
  if (!e.inverse_dynamics.empty()) return DynamicsForm::newton_euler;
  return DynamicsForm::mass_matrix;
}

}  // namespace eomgen
