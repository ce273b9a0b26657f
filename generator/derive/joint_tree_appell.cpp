/// @file Appell's equations of a tree of joints with ball or free joints (Hiller §4.3–4.4), from
/// the spatial recursions (spatial/joint_tree_dynamics.hpp) instead of the acceleration energy:
/// projecting the bodies' Newton–Euler equations onto the partial velocities of the pseudo-
/// velocities s is what ∂S/∂s' does, so M_s comes from the composite-body recursion and
/// f_s = −τ(q, s, s' = 0) + Wᵀ(Q − ∂V/∂q − ∂R/∂q') with q' = W(q)·s.
#include "derive/joint_tree_accelerations.hpp"
#include "derive/methods.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// s0 from its definitions s = Y(q) q' at the model's initial q and q'
std::vector<double> initial_pseudo_velocities(const Symbols& s, const JointVelocities& v) {
  GiNaC::exmap at = s.default_parameter_values();
  for (std::size_t j = 0; j < s.num_coordinates(); ++j) {
    at[s.coordinates[j]] = s.initial_coordinates[j];
    at[s.velocities[j]] = s.initial_velocities[j];
  }
  at[s.time] = 0;
  std::vector<double> out;
  for (const NamedSymbolic& d : v.definitions) {
    ex x = d.expression.subs(at).evalf();
    out.push_back(GiNaC::is_a<GiNaC::numeric>(x) ? GiNaC::ex_to<GiNaC::numeric>(x).to_double() : 0.0);
  }
  return out;
}

// the intermediates that `used` needs, in their order: the frame recursion's angular velocities
// of a quaternion's frame, which the tree does not use, would fill pages of the printed equations
std::vector<Intermediate> needed(const std::vector<Intermediate>& all, const std::vector<ex>& used) {
  GiNaC::exset symbols;
  auto collect = [&](const ex& x) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
      if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
  };
  for (const ex& x : used) collect(x);
  std::vector<bool> keep(all.size(), false);
  for (std::size_t i = all.size(); i-- > 0;)
    if (symbols.count(all[i].symbol)) keep[i] = true, collect(all[i].definition);
  std::vector<Intermediate> out;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (keep[i]) out.push_back(all[i]);
  return out;
}

}  // namespace

Equations derive_joint_tree_appell(const Model& model, const Mechanics& mech) {
  const JointVelocities& v = *mech.tree_velocities;
  const Symbols& s = model.symbols;
  std::size_t n = s.num_coordinates(), k = v.symbols.size();
  Equations e;
  e.model_name = model.name;
  e.title = model.title;
  e.method = "appell";
  e.source = model.source;
  e.symbols = s;
  e.symbols.velocities = v.symbols;
  e.symbols.initial_velocities = initial_pseudo_velocities(s, v);
  e.coordinate_velocities = s.velocities;
  e.coordinate_rates = v.coordinate_rates;
  e.pseudo_velocity_definitions = v.definitions;
  e.degrees_of_freedom = k;
  e.intermediates = mech.intermediates;
  MotionSymbols motion = motion_symbols(e.symbols);
  for (const auto& x : s.velocities) motion.symbols.insert(x);
  for (const Intermediate& i : mech.intermediates) motion.symbols.insert(i.symbol);

  GiNaC::exmap rates;
  for (std::size_t j = 0; j < n; ++j) rates[s.velocities[j]] = v.coordinate_rates[j];
  std::vector<ex> applied(n);
  for (std::size_t j = 0; j < n; ++j)
    applied[j] = (mech.generalized_force[j] - mech.potential_gradient[j] - mech.dissipation.diff(s.velocities[j])).subs(rates);
  e.mass_matrix = GiNaC::matrix(unsigned(k), unsigned(k));
  e.forcing = *mech.tree_bias_forces;
  for (std::size_t j = 0; j < n; ++j)
    for (const auto& [c, w] : v.rate_matrix[j]) e.forcing[c] += w * applied[j];
  for (unsigned c = 0; c < k; ++c) {
    e.forcing[c] = tidy(e.forcing[c], motion);
    for (unsigned d = c; d < k; ++d) e.mass_matrix(c, d) = e.mass_matrix(d, c) = tidy((*mech.composite_mass_matrix)(c, d), motion);
  }
  take_newton_euler_recursion(mech, e);
  e.coordinate_parents = mech.coordinate_parents;
  for (const FrameLink& l : model.frame_links)
    if (l.joint && l.joint->spherical())
      e.quaternions.push_back({std::size_t(l.joint->quaternion[0]), std::size_t(l.joint->quaternion[1]),
                               std::size_t(l.joint->quaternion[2]), std::size_t(l.joint->quaternion[3])});
  // an [energy] kinetic in a quaternion's rates is written in the angular velocity
  ex kinetic = kinetic_energy_of(mech), in_velocities = kinetic.subs(rates);
  e.kinetic_energy = in_velocities.is_equal(kinetic) ? kinetic : tidy(in_velocities, motion);
  e.potential_energy = mech.potential_energy;
  e.dissipation = tidy(mech.dissipation.subs(rates), motion);
  for (const NamedSymbolic& o : model.outputs) e.outputs.push_back({o.name, tidy(o.expression.subs(rates), motion)});
  e.conserves_energy_without_inputs = conserves_energy_without_inputs(mech, s);
  add_joint_tree_accelerations(model, mech, e);
  std::vector<ex> used = e.forcing;
  if (e.joint_tree_accelerations())
    for (const Intermediate& i : e.joint_tree_accelerations()->intermediates) used.push_back(i.definition);
  for (unsigned c = 0; c < k; ++c)
    for (unsigned d = 0; d < k; ++d) used.push_back(e.mass_matrix(c, d));
  if (const NewtonEulerRecursion* recursion = e.newton_euler()) {
    used.insert(used.end(), recursion->inverse_dynamics.begin(), recursion->inverse_dynamics.end());
    for (const Intermediate& i : recursion->acceleration_intermediates) used.push_back(i.definition);
    if (recursion->bodies_gradient) {
      std::vector<ex> gradient = written_expressions(*recursion->bodies_gradient);
      used.insert(used.end(), gradient.begin(), gradient.end());
    }
  }
  for (const BodyKinematics& b : mech.bodies) used.insert(used.end(), b.position.begin(), b.position.end());
  for (const NamedSymbolic& o : e.outputs) used.push_back(o.expression);
  for (const DrawnBody& b : model.drawing) {  // the header's body_poses
    used.insert(used.end(), b.position.begin(), b.position.end());
    for (unsigned i = 0; i < 9; ++i) used.push_back(b.rotation.op(i));
  }
  used.insert(used.end(), {e.kinetic_energy, e.potential_energy, e.dissipation});
  e.intermediates = needed(mech.intermediates, used);
  return e;
}

}  // namespace eomgen
