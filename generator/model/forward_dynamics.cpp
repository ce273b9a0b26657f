/// @file The check of a form of forward dynamics asked for instead of eomgen's choice: for the
/// articulated-body recursion a model that it can solve (kinematics/particle_tree).
#include <fmt/format.h>

#include "kinematics/particle_tree.hpp"
#include "model/model.hpp"

namespace eomgen {

void check_forward_dynamics(const Model& model, SourceLocation where, Diagnostics& diagnostics) {
  if (model.forward_dynamics != ForwardDynamics::articulated) return;
  if (model.method != "lagrange2")
    diagnostics.error(where, "--forward-dynamics",
                      fmt::format("the articulated-body recursion solves Lagrange's equations of the second kind, not method '{}'",
                                  model.method),
                      "leave --forward-dynamics out, or use method = \"lagrange2\"");
  else if (ParticleTree tree = find_particle_tree(model); !tree.found())
    diagnostics.error(where, "--forward-dynamics",
                      "the articulated-body recursion needs a tree of particles, and this model is not one: " + tree.why_not,
                      "leave --forward-dynamics out, or use mass_matrix (M = L D L^T)");
}

}  // namespace eomgen
