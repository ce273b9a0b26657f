#include "model/variants.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace eomgen {

using GiNaC::ex;

namespace {

void apply(ex& e, const GiNaC::exmap& s) { e = e.subs(s).eval(); }

void apply(Vector3& v, const GiNaC::exmap& s) {
  for (ex& e : v) apply(e, s);
}

void apply(GiNaC::matrix& m, const GiNaC::exmap& s) {
  for (unsigned i = 0; i < m.rows(); ++i)
    for (unsigned j = 0; j < m.cols(); ++j) apply(m(i, j), s);
}

// an expression that no longer evaluates (a division by a neglected parameter) stops the variant here
void check_finite(const ex& e, const std::string& where) {
  try {
    (void)e.normal();
  } catch (const std::exception& why) {
    throw std::invalid_argument(fmt::format("{} breaks: {}", where, why.what()));
  }
}

}  // namespace

void substitute_everywhere(Model& m, const GiNaC::exmap& s) {
  auto turn = [&](ElementaryRotation& r) { apply(r.angle, s), apply(r.direction, s), apply(r.constant, s); };
  try {
    for (Particle& p : m.particles) apply(p.mass, s), apply(p.position, s);
    for (RigidBody& b : m.rigid_bodies) {
      apply(b.mass, s), apply(b.center, s), apply(b.inertia, s), apply(b.rotation.matrix, s);
      for (ElementaryRotation& r : b.rotation.sequence) turn(r);
    }
    apply(m.gravity, s), apply(m.kinetic, s), apply(m.potential, s), apply(m.dissipation, s);
    for (ex& q : m.generalized_force) apply(q, s);
    for (PointForce& f : m.point_forces) apply(f.at, s), apply(f.force, s);
    for (BodyTorque& t : m.torques) apply(t.torque, s);
    for (Constraint& c : m.constraints) apply(c.expression, s);
    for (NamedSymbolic& v : m.pseudo_velocities) apply(v.expression, s);
    for (NamedSymbolic& o : m.outputs) apply(o.expression, s);
    auto place = [&](FramePlacement& p) {
      apply(p.local, s), apply(p.relative, s);
      for (ElementaryRotation& r : p.sequence) turn(r);
    };
    for (Particle& p : m.particles) place(p.placement);
    for (RigidBody& b : m.rigid_bodies) place(b.placement);
    // a joint no longer describes a frame whose coordinate is held, tied or approximated: the frame
    // recursion (substituted here) derives it then; parameters and inputs only change its numbers
    bool coordinates_change = std::any_of(s.begin(), s.end(), [&](const auto& k) {
      return std::any_of(m.symbols.coordinates.begin(), m.symbols.coordinates.end(),
                         [&](const GiNaC::realsymbol& q) { return k.first.has(q); });
    });
    for (FrameLink& f : m.frame_links) {
      apply(f.relative_rotation, s), apply(f.relative_origin, s), apply(f.rotation, s), apply(f.origin, s);
      for (ElementaryRotation& r : f.sequence) turn(r);
      if (f.joint && coordinates_change) f.joint.reset();
      else if (f.joint) apply(f.joint->axis, s), apply(f.joint->anchor, s), apply(f.joint->placement, s), apply(f.joint->placement_origin, s);
    }
    for (Intermediate& i : m.intermediates) apply(i.definition, s);
    for (DrawnBody& d : m.drawing) {
      apply(d.position, s), apply(d.rotation, s);
      for (Shape& shape : d.shapes) apply(shape.size, s), apply(shape.offset, s), apply(shape.axis, s);
    }
  } catch (const std::exception& why) {
    throw std::invalid_argument(fmt::format("an expression breaks: {}", why.what()));
  }
  check_finite(m.kinetic + m.potential + m.dissipation, "the energy");
  for (const Particle& p : m.particles) check_finite(p.mass + p.position[0] + p.position[1] + p.position[2], "particle " + p.name);
}

Model freeze_coordinates(const Model& model, const std::vector<std::size_t>& frozen, const std::vector<double>& values) {
  Model m = model;
  GiNaC::exmap held;
  for (std::size_t k = 0; k < frozen.size(); ++k) {
    held[model.symbols.coordinates[frozen[k]]] = values[k];
    held[model.symbols.velocities[frozen[k]]] = 0;
  }
  substitute_everywhere(m, held);
  // a constraint that only held the frozen coordinates is gone
  m.constraints.erase(std::remove_if(m.constraints.begin(), m.constraints.end(),
                                     [](const Constraint& c) { return c.expression.normal().is_zero(); }),
                      m.constraints.end());
  std::vector<std::size_t> order = frozen;
  std::sort(order.rbegin(), order.rend());
  for (std::size_t i : order) {
    m.symbols.remove_coordinate(i);
    m.generalized_force.erase(m.generalized_force.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return m;
}

Model tie_coordinates(const Model& model, const std::vector<std::pair<std::size_t, GiNaC::ex>>& ties) {
  Model m = model;
  const Symbols& s = model.symbols;
  // q_j = g(q), der(q_j) = Σ ∂g/∂q_k der(q_k): a holonomic constraint solved for q_j (a rigid link)
  GiNaC::exmap tied;
  for (const auto& [j, g] : ties) {
    ex rate = 0;
    for (std::size_t k = 0; k < s.coordinates.size(); ++k) rate += g.diff(s.coordinates[k]) * s.velocities[k];
    tied[s.coordinates[j]] = g, tied[s.velocities[j]] = rate;
  }
  // a generalized force on a tied coordinate acts through ∂g/∂q_k on the others (virtual work)
  for (const auto& [j, g] : ties)
    for (std::size_t k = 0; k < s.coordinates.size(); ++k)
      if (k != j) m.generalized_force[k] += model.generalized_force[j] * g.diff(s.coordinates[k]);
  substitute_everywhere(m, tied);
  std::vector<std::size_t> order;
  for (const auto& tie : ties) order.push_back(tie.first);
  std::sort(order.rbegin(), order.rend());
  for (std::size_t i : order) {
    m.symbols.remove_coordinate(i);
    m.generalized_force.erase(m.generalized_force.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return m;
}

Model apply_variant(const Model& model, const Variant& v) {
  const Symbols& s = model.symbols;
  GiNaC::exmap changed;
  for (std::size_t i : v.neglect) changed[s.parameters[i]] = 0;
  for (const auto& [i, value] : v.replace) changed[s.parameters[i]] = value;
  for (const auto& [i, quadratic] : v.small_angle) {
    const GiNaC::realsymbol& q = s.coordinates[i];
    changed[GiNaC::sin(q)] = q;
    changed[GiNaC::cos(q)] = quadratic ? 1 - q * q / 2 : ex(1);
  }
  Model m = model;
  substitute_everywhere(m, changed);
  // a rotation given as a sequence of angles no longer matches its approximated matrix
  auto approximated = [&](std::vector<ElementaryRotation>& sequence) {
    for (const auto& [i, quadratic] : v.small_angle)
      for (const ElementaryRotation& r : sequence)
        if (r.angle.has(s.coordinates[i])) return sequence.clear();
  };
  for (RigidBody& b : m.rigid_bodies) approximated(b.rotation.sequence), approximated(b.placement.sequence);
  for (FrameLink& f : m.frame_links) approximated(f.sequence);
  if (!v.tie.empty()) m = tie_coordinates(m, v.tie);
  // the frozen coordinates by name: the ties have removed some
  std::vector<std::size_t> frozen;
  std::vector<double> held;
  for (std::size_t i : v.freeze)
    for (std::size_t k = 0; k < m.symbols.coordinates.size(); ++k)
      if (m.symbols.coordinate_names[k] == s.coordinate_names[i]) frozen.push_back(k), held.push_back(s.initial_coordinates[i]);
  m = freeze_coordinates(m, frozen, held);
  m.name = model.name + "_" + v.name;
  m.title = model.title + " (variant " + v.name + ")";
  return m;
}

Model apply_scene(const Model& model, const Scene& scene) {
  Model m = model;
  Symbols& s = m.symbols;
  for (const auto& [i, value] : scene.set) s.parameter_defaults[i] = value;
  GiNaC::exmap inputs;
  for (const auto& [i, u] : scene.inputs) inputs[s.inputs[i]] = u;
  if (!inputs.empty()) substitute_everywhere(m, inputs);
  for (const auto& [name, value] : scene.initial)
    for (std::size_t i = 0; i < s.coordinates.size(); ++i) {
      if (name == s.coordinate_names[i]) s.initial_coordinates[i] = value, s.initial_coordinate_expressions[i] = value;
      if (name == "der(" + s.coordinate_names[i] + ")") s.initial_velocities[i] = value, s.initial_rate_expressions[i] = value;
    }
  return m;
}

}  // namespace eomgen
