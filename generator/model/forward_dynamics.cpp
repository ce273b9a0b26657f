/// @file The check of a form of forward dynamics asked for instead of eomgen's choice: for the
/// articulated-body recursion a model that it can solve: a tree of particles (kinematics/particle_tree)
/// or of hinges and slides (spatial/joint_tree_forward_dynamics).
#include <fmt/format.h>

#include "kinematics/particle_tree.hpp"
#include "model/model.hpp"
#include "spatial/joint_tree_forward_dynamics.hpp"

namespace eomgen {

void check_forward_dynamics(const Model& model, SourceLocation where, Diagnostics& diagnostics) {
  if (model.forward_dynamics != ForwardDynamics::articulated) return;
  if (model.method != "lagrange2")
    diagnostics.error(where, "--forward-dynamics",
                      fmt::format("the articulated-body recursion solves Lagrange's equations of the second kind, not method '{}'",
                                  model.method),
                      "leave --forward-dynamics out, or use method = \"lagrange2\"");
  else if (ParticleTree tree = find_particle_tree(model); !tree.found())
    if (auto why = why_not_articulated_joint_tree(model))
      diagnostics.error(where, "--forward-dynamics",
                        fmt::format("the articulated-body recursion needs a tree of particles or of hinges and slides, and this "
                                    "model is neither: as particles, {}; as joints, {}", tree.why_not, *why),
                        "leave --forward-dynamics out, or use mass_matrix (M = L D L^T)");
}

}  // namespace eomgen
