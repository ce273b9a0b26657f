#include "emit/dynamics_form.hpp"

namespace eomgen {

DynamicsForm dynamics_form(const Equations& e) {
  if (e.momentum()) return DynamicsForm::momentum;
  if (e.articulated()) return DynamicsForm::particle_tree;
  if (e.newton_euler()) return DynamicsForm::newton_euler;
  return DynamicsForm::mass_matrix;
}

}  // namespace eomgen
