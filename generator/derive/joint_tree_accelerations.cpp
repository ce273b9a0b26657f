#include "derive/joint_tree_accelerations.hpp"

#include "common/deadline.hpp"
#include "spatial/joint_tree_forward_dynamics.hpp"

namespace eomgen {

using GiNaC::ex;

void add_joint_tree_accelerations(const Model& model, const Mechanics& mech, Equations& e) {
  if (model.forward_dynamics == ForwardDynamics::mass_matrix || mech.tree_links.empty() || !mech.bodies_gradient) return;
  if (model.forward_dynamics == ForwardDynamics::chosen && !articulated_body_may_pay(mech.tree_links)) return;
  if (why_not_articulated_joint_tree(model)) return;
  // the applied part of τ_j is a_j q''_j + the rest (an [energy] kinetic of no cross terms)
  const std::vector<ex>& applied = mech.bodies_gradient->applied_inverse_dynamics;
  std::vector<ex> forces, joint_inertias;
  for (std::size_t j = 0; j < applied.size(); ++j) {
    ex tau = applied[j].expand();
    joint_inertias.push_back(tau.coeff(mech.acceleration_symbols[j]));
    tau = (tau - joint_inertias.back() * mech.acceleration_symbols[j]).expand();
    for (const GiNaC::symbol& a : mech.acceleration_symbols)
      if (tau.has(a) || joint_inertias.back().has(a)) return;
    forces.push_back(-tau);
  }
  NewtonEulerRecursion* recursion = e.newton_euler();
  if (!recursion) return;
  derivation_stage("the articulated-body algorithm");
  recursion->joint_tree_accelerations = joint_tree_accelerations(mech.tree_links, model.gravity, forces, joint_inertias);
  recursion->joint_tree_accelerations->asked = model.forward_dynamics == ForwardDynamics::articulated;
}

}  // namespace eomgen
