/// @file The check of a form of forward dynamics asked for instead of eomgen's choice: for the
/// articulated-body recursion a model that it can solve: a tree of particles (kinematics/particle_tree)
/// or of joints (spatial/joint_tree_forward_dynamics).
#include <optional>
#include <string>

#include <fmt/format.h>

#include "kinematics/particle_tree.hpp"
#include "model/model.hpp"
#include "spatial/joint_tree_forward_dynamics.hpp"

namespace eomgen {

void check_forward_dynamics(const Model& model, SourceLocation where, Diagnostics& diagnostics) {
  if (model.forward_dynamics != ForwardDynamics::articulated) return;
  std::optional<std::string> as_joints = why_not_articulated_joint_tree(model);
  if (!as_joints) return;
  if (!articulated_method(model))
    diagnostics.error(where, "--forward-dynamics",
                      fmt::format("the articulated-body recursion solves Lagrange's equations of the second kind (Appell's "
                                  "for a tree with ball or free joints), not method '{}'",
                                  model.method),
                      "leave --forward-dynamics out, or use method = \"lagrange2\"");
  else if (model.method != "lagrange2")
    diagnostics.error(where, "--forward-dynamics", "the articulated-body recursion needs a tree of joints, and this model is not one: " + *as_joints,
                      "leave --forward-dynamics out");
  else if (ParticleTree tree = find_particle_tree(model); !tree.found())
    diagnostics.error(where, "--forward-dynamics",
                      fmt::format("the articulated-body recursion needs a tree of particles or of joints, and this model "
                                  "is neither: as particles, {}; as joints, {}",
                                  tree.why_not, *as_joints),
                      "leave --forward-dynamics out, or use mass_matrix (M = L D L^T)");
}

}  // namespace eomgen
