#include <fmt/format.h>

#include "kinematics/rolling_contact.hpp"
#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

std::optional<std::size_t> ModelBuilder::coordinate_index(const NamedExpression& g, const std::string& key) {
  auto found = m_.symbols.by_name.find(g.name);
  if (found != m_.symbols.by_name.end() && found->second.kind == SymbolKind::coordinate) return found->second.index;
  d_.error(g.where, key + "." + g.name, fmt::format("'{}' is not a coordinate", g.name),
           suggest(g.name, m_.symbols.coordinate_names, "coordinates"));
  return std::nullopt;
}

void ModelBuilder::read_energies_and_forces() {
  if (!f_.gravity.empty()) m_.gravity = vector(f_.gravity, allow_parameters | allow_time, "gravity");
  if (f_.kinetic) m_.kinetic = parse(*f_.kinetic, allow_configuration | allow_velocities, "the kinetic energy").value_or(0);
  if (f_.potential) m_.potential = parse(*f_.potential, allow_configuration, "the potential energy").value_or(0);
  if (f_.dissipation) m_.dissipation = parse(*f_.dissipation, allow_configuration | allow_velocities, "the dissipation function").value_or(0);
  for (const ForceEntry& f : f_.forces) {
    switch (f.kind) {
      case ForceEntry::Kind::generalized:
        for (const NamedExpression& g : f.generalized) {
          auto index = coordinate_index(g, f.key + ".generalized");
          auto e = parse(g.expression, allow_everything, "a force");
          if (index && e) m_.generalized_force[*index] += *e;
        }
        break;
      case ForceEntry::Kind::point:
        m_.point_forces.push_back({vector(f.at, allow_configuration, "a position"), vector(f.force, allow_everything, "a force")});
        break;
      case ForceEntry::Kind::torque: read_torque(f); break;
    }
  }
}

void ModelBuilder::read_torque(const ForceEntry& f) {
  Vector3 torque = vector(f.torque, allow_everything, "a torque");
  for (std::size_t i = 0; i < f_.rigid_bodies.size(); ++i)
    if (f_.rigid_bodies[i].name == f.body) {
      m_.torques.push_back({i, torque, f.inertial_frame});
      return;
    }
  std::vector<std::string> names;
  for (const RigidBodyEntry& b : f_.rigid_bodies) names.push_back(b.name);
  d_.error(f.body_where, f.key + ".body", fmt::format("'{}' is not a rigid body", f.body),
           suggest(f.body, names, "rigid bodies"));
}

void ModelBuilder::read_constraints() {
  for (const ConstraintEntry& c : f_.constraints) {
    if (c.kind == ConstraintEntry::Kind::rolls) {
      read_rolling(c);
      continue;
    }
    bool holonomic = c.kind == ConstraintEntry::Kind::holonomic;
    auto e = holonomic ? parse(c.expression, allow_configuration, "a holonomic constraint")
                       : parse(c.expression, allow_configuration | allow_velocities, "a nonholonomic constraint");
    if (!e) continue;
    if (!holonomic) check_linear_in_velocities(*e, c.expression, "a nonholonomic constraint");
    add_constraint(c, holonomic, *e, c.name.empty() ? fmt::format("c{}", m_.constraints.size() + 1) : c.name);
  }
  for (const NamedExpression& p : f_.pseudo_velocities) {
    std::string key = "pseudo_velocities." + p.name;
    if (!is_identifier(p.name) || is_reserved_name(p.name) || m_.symbols.by_name.count(p.name))
      d_.error(p.where, key, fmt::format("'{}' cannot name a pseudo-velocity", p.name),
               "use a new name that is not a parameter, coordinate, input or function");
    auto e = parse(p.expression, allow_configuration | allow_velocities, "a pseudo-velocity");
    if (!e) continue;
    check_linear_in_velocities(*e, p.expression, "a pseudo-velocity");
    m_.pseudo_velocities.push_back({p.name, *e});
  }
}

void ModelBuilder::add_constraint(const ConstraintEntry& c, bool holonomic, const ex& e, const std::string& name) {
  if (!is_cpp_identifier(name))
    d_.error(c.name_where, c.key + ".name", fmt::format("'{}' is not a C++ identifier", name),
             "a constraint's name becomes part of its multiplier's name, lambda_NAME");
  for (const Constraint& other : m_.constraints)
    if (other.name == name)
      d_.error(c.name_where.line ? c.name_where : c.where, c.key + ".name",
               fmt::format("two constraints are named '{}'", name), "give each constraint its own name");
  m_.constraints.push_back({holonomic, e, c.key, name});
}

void ModelBuilder::read_rolling(const ConstraintEntry& c) {
  auto body = std::find_if(m_.rigid_bodies.begin(), m_.rigid_bodies.end(),
                           [&](const RigidBody& b) { return b.name == c.body; });
  if (body == m_.rigid_bodies.end()) {
    std::vector<std::string> names;
    for (const RigidBody& b : m_.rigid_bodies) names.push_back(b.name);
    d_.error(c.body_where, c.key + ".rolls.body", fmt::format("'{}' is not a rigid body", c.body),
             suggest(c.body, names, "rigid bodies"));
    return;
  }
  // the contact conditions differentiate the wheel's rotation and centre in q, which recursive
  // kinematics keeps as the frames' quantities: the Whipple bicycle's then lost rank
  if (m_.recursive_kinematics) {
    d_.error(c.body_where, c.key + ".rolls.body",
             fmt::format("'{}' rolls, whose contact conditions need its rotation written out in q, but the model takes "
                         "recursive kinematics (its frames carry joints)",
                         c.body),
             "place the wheel's frames by rotations and origins instead of joints (rot_z(psi), origin "
             "[\"x\", \"y\", \"0\"])");
    return;
  }
  auto radius = parse(c.radius, allow_parameters, "a radius");
  Vector3 axis = vector(c.axis, allow_parameters, "an axis");
  if (!radius) return;
  if ((axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).is_zero()) {
    d_.error(c.axis[0].where, c.key + ".rolls.axis", "the disk's axis is zero", "give its direction in the body frame, e.g. [0, 1, 0]");
    return;
  }
  // an oblique axis puts √(axis·axis) and √(1 − n_z²) of no known angle into every constraint: the
  // derivation then takes seconds and fails in GiNaC's polynomial arithmetic (found by fuzzing)
  if (std::count_if(axis.begin(), axis.end(), [](const ex& a) { return !a.is_zero(); }) != 1) {
    d_.error(c.axis[0].where, c.key + ".rolls.axis",
             fmt::format("the disk's axis must lie along x, y or z of the body's frame; [{}, {}, {}] does not", c.axis[0].text,
                         c.axis[1].text, c.axis[2].text),
             "turn the body instead: give it (or its frame) the rotation that brings the disk's axis onto one of the "
             "frame's axes, and write that axis, [0, 0, 1] say");
    return;
  }
  std::optional<RollingContact> found = rolling_contact(body->center, body->rotation, axis, *radius, m_.symbols);
  if (!found) {
    d_.error(c.axis[0].where, c.key + ".rolls.axis",
             "the disk lies flat at the initial state (its axis is vertical), so no point of its rim is the lowest",
             "check the axis in the body frame and the rotations of the body and its frames, and start it tilted "
             "away from flat");
    return;
  }
  const RollingContact& contact = *found;
  std::string base = c.name.empty() ? c.body : c.name;
  if (!contact.height.is_zero()) add_constraint(c, true, contact.height, base + "_contact");
  add_constraint(c, false, contact.slip_x, base + "_slip_x");
  add_constraint(c, false, contact.slip_y, base + "_slip_y");
}

void ModelBuilder::check_linear_in_velocities(const ex& e, const ExpressionText& text, const char* what) {
  const auto& v = m_.symbols.velocities;
  bool has_velocity = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    ex di = e.diff(v[i]);
    has_velocity = has_velocity || !di.is_zero();
    for (std::size_t j = i; j < v.size(); ++j)
      if (!di.diff(v[j]).expand().is_zero()) {
        d_.error(text.where, text.key,
                 fmt::format("{} must be linear in the velocities; it is not, in der({}){}", what,
                             m_.symbols.coordinate_names[i],
                             i == j ? "" : " and der(" + m_.symbols.coordinate_names[j] + ")"),
                 "write it as a(q,t)*der(q) + b(q,t)");
        return;
      }
  }
  if (!has_velocity)
    d_.error(text.where, text.key, fmt::format("{} without any velocity", what),
             "a relation between coordinates alone is holonomic: write holonomic = \"...\"");
}

}  // namespace eomgen
