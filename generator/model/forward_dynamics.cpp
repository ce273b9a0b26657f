/// @file The check of [model] forward_dynamics: a known form, and for "articulated" a model the
/// articulated-body recursion can solve (kinematics/particle_tree).
#include <fmt/format.h>

#include "kinematics/particle_tree.hpp"
#include "model/model.hpp"

namespace eomgen {

void check_forward_dynamics(const ModelFile& file, const Model& model, Diagnostics& diagnostics) {
  const std::string& form = file.forward_dynamics;
  if (form != "auto" && form != "mass_matrix" && form != "articulated")
    diagnostics.error(file.forward_dynamics_where, "model.forward_dynamics",
                      fmt::format("unknown forward dynamics '{}'", form),
                      "use \"auto\" (the default: the articulated-body recursion for a tree of particles with many "
                      "coordinates, M = L D L^T otherwise), \"mass_matrix\" or \"articulated\"");
  if (form != "articulated" || !diagnostics.empty()) return;
  if (file.method != "lagrange2")
    diagnostics.error(file.forward_dynamics_where, "model.forward_dynamics",
                      fmt::format("the articulated-body recursion solves Lagrange's equations of the second kind, not method '{}'",
                                  file.method),
                      "use method = \"lagrange2\", or forward_dynamics = \"auto\"");
  else if (ParticleTree tree = find_particle_tree(model); !tree.found())
    diagnostics.error(file.forward_dynamics_where, "model.forward_dynamics",
                      "the articulated-body recursion needs a tree of particles, and this model is not one: " + tree.why_not,
                      "use forward_dynamics = \"auto\" or \"mass_matrix\" (M = L D L^T)");
}

}  // namespace eomgen
