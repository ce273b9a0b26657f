#include "emit/cpp_header_summary.hpp"

#include "emit/dynamics_form.hpp"

namespace eomgen {

namespace {

std::string equations_and_state(const Equations& e) {
  const DynamicsForm form = dynamics_form(e);
  if (e.method == "hamilton")
    return "Hamilton's canonical equations q' = dH/dp, p' = -dH/dq + Q, written as M = I, f = p'; state x = [q; p].";
  if (e.uses_pseudo_velocities())
    return "Appell's equations M(q,t) s' = f(q, s, u, t) with q' = W(q,t) s + w(q,t); state x = [q; s].";
  if (e.has_multipliers)
    return "Lagrange I: M(q,t) q'' = f(q, q', u, t) + C(q,t)^T lambda with C q'' + gamma = 0; state x = [q; q'].";
  if (form == DynamicsForm::newton_euler)
    return "Equations of motion M(q,t) q'' = f(q, q', u, t); state x = [q; q'].\n// Recursive kinematics: each "
           "function computes the frames' and bodies' quantities it needs (k_...) first; jacobian_state and\n"
           "// linearization differentiate the Newton-Euler inverse dynamics tau = M q'' - f (forward mode).";
  if (form == DynamicsForm::particle_tree)
    return "Equations of motion M(q,t) q'' = f(q, q', u, t); state x = [q; q'].\n// Forward dynamics: rhs solves "
           "for q'' by the articulated-body recursion of the particles' tree (O(n));\n// mass_matrix, forcing "
           "and jacobian_state use the same tree (M_jl = m S_j . S_l; jacobian_state entry by entry from the\n"
           "// recursion's factors, O(1) operations each, without M^-1).";
  return "Equations of motion M(q,t) q'' = f(q, q', u, t); state x = [q; q'].";
}

}  // namespace

std::string header_summary(const Equations& e, const std::string& functions) {
  std::string out = equations_and_state(e);
  if (e.joint_tree_accelerations())
    out += "\n// Forward dynamics: rhs solves for the accelerations by the articulated-body algorithm over the joints "
           "(O(n), without M).";
  if (functions.find("tree_loops_mass_matrix_and_forcing(tree") != std::string::npos)
    out += "\n// M and f: loops over the links' tables (detail::tree_loops_mass_matrix_and_forcing).";
  return out;
}

}  // namespace eomgen
