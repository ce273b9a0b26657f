// Ball and free joints (FrameEntry::joint with type "ball" or "free"): MJCF's ball and free.
// The frame, placed by R_p and o_p, is turned by the unit quaternion (w, x, y, z) of four
// coordinates, R(q) of model/quaternion.hpp, which any nonzero quaternion makes a rotation:
//   ball: R = R_p·R(q), o = o_p + R_p·(a − R(q)·a)   (a: the centre, frame coordinates)
//   free: R = R_p·R(q), o = o_p + R_p·(x, y, z)
// Its velocities are the components of the frame's angular velocity relative to the parent in
// the frame's own axes, ω (pseudo-velocities, Hiller §4.4), and q' = ½ q ⊗ (0, ω), which keeps
// |q| constant. The quaternion's initial rates follow from the initial ω.
#include <algorithm>

#include <fmt/format.h>

#include "model/model_builder.hpp"
#include "model/quaternion.hpp"

namespace eomgen {

using GiNaC::ex;


std::optional<std::vector<int>> ModelBuilder::joint_coordinates(const std::vector<std::string>& names,
                                                                const SourceLocation& where, const std::string& key) {
  const Symbols& s = m_.symbols;
  std::vector<int> out;
  for (const std::string& name : names) {
    auto found = std::find(s.coordinate_names.begin(), s.coordinate_names.end(), name);
    if (found == s.coordinate_names.end()) {
      d_.error(where, key, fmt::format("'{}' is not a coordinate", name),
               s.coordinate_names.empty() ? "declare it under [coordinates]" : suggest(name, s.coordinate_names, "coordinates"));
      return std::nullopt;
    }
    int index = int(found - s.coordinate_names.begin());
    if (std::find(out.begin(), out.end(), index) != out.end()) {
      d_.error(where, key, fmt::format("'{}' is named twice", name), "give each component its own coordinate");
      return std::nullopt;
    }
    out.push_back(index);
  }
  return out;
}

bool ModelBuilder::name_angular_velocity(const JointEntry& j, FrameLink::Joint& joint) {
  for (const std::string& name : j.angular_velocity) {
    bool taken = m_.symbols.by_name.count(name) > 0 || angular_velocity_names_.count(name) > 0;
    if (!is_cpp_identifier(name) || is_reserved_name(name) || taken) {
      d_.error(j.angular_velocity_where, j.key + ".angular_velocity",
               fmt::format("'{}' cannot name a velocity{}", name, taken ? ": the name is taken" : ""),
               "give each component a new name of letters, digits and _, e.g. wx, wy, wz");
      return false;
    }
    angular_velocity_names_.insert(name);
    joint.angular_velocity.emplace_back(name);
  }
  return true;
}

// q0' = ½ q0 ⊗ (0, ω0): the quaternion's rates that the initial angular velocity gives
void ModelBuilder::set_quaternion_rates(const JointEntry& j, const std::array<int, 4>& q) {
  Symbols& s = m_.symbols;
  std::vector<ex> w(3, 0);
  for (std::size_t k = 0; k < j.initial_angular_velocity.size(); ++k)
    constant(j.initial_angular_velocity[k], "an initial angular velocity", &w[k]);
  std::array<ex, 4> q0;
  for (std::size_t k = 0; k < 4; ++k) {
    std::size_t c = std::size_t(q[k]);
    q0[k] = s.initial_coordinate_expressions[c];
    if (!s.initial_rate_expressions[c].is_zero())
      d_.error(j.quaternion_where, j.key + ".quaternion",
               fmt::format("coordinate '{}' has an initial rate, but a quaternion's rates follow from the angular velocity",
                           s.coordinate_names[c]),
               "remove its rate and give the joint initial_angular_velocity = [wx, wy, wz]");
  }
  if ((q0[0] * q0[0] + q0[1] * q0[1] + q0[2] * q0[2] + q0[3] * q0[3]).subs(s.default_parameter_values()).evalf().is_zero())
    d_.error(j.quaternion_where, j.key + ".quaternion", "the initial quaternion is zero, which is no orientation",
             "give its coordinates initial values, e.g. qw = 1 for the placement itself");
  std::array<ex, 4> rate = quaternion_rates(q0, {w[0], w[1], w[2]});
  for (std::size_t k = 0; k < 4; ++k) {
    std::size_t c = std::size_t(q[k]);
    s.initial_rate_expressions[c] = rate[k];
    auto value = constant_value(rate[k], s);
    s.initial_velocities[c] = value ? *value : 0;
  }
}

std::optional<FrameLink::Joint> ModelBuilder::turn_by_quaternion(const JointEntry& j, Rotation& relative, Vector3& origin) {
  if (j.quaternion.size() != 4 || j.angular_velocity.size() != 3) return std::nullopt;  // reported by the parser
  FrameLink::Joint joint;
  joint.type = j.type == "free" ? FrameLink::Joint::Type::free : FrameLink::Joint::Type::ball;
  auto q = joint_coordinates(j.quaternion, j.quaternion_where, j.key + ".quaternion");
  if (!q || !name_angular_velocity(j, joint)) return std::nullopt;
  std::copy(q->begin(), q->end(), joint.quaternion.begin());
  set_quaternion_rates(j, joint.quaternion);
  const Symbols& s = m_.symbols;
  const auto c = [&](int k) { return ex(s.coordinates[std::size_t(k)]); };
  GiNaC::matrix R = quaternion_rotation({c(joint.quaternion[0]), c(joint.quaternion[1]), c(joint.quaternion[2]), c(joint.quaternion[3])});
  Vector3 moved{0, 0, 0};
  if (joint.type == FrameLink::Joint::Type::free) {
    if (j.position.size() != 3) return std::nullopt;
    auto x = joint_coordinates(j.position, j.position_where, j.key + ".position");
    if (!x) return std::nullopt;
    for (std::size_t k = 0; k < 3; ++k) joint.position[k] = (*x)[k], moved[k] = c((*x)[k]);
  } else if (!j.anchor.empty()) {
    joint.anchor = vector(j.anchor, allow_parameters, "a joint anchor");
    for (unsigned a = 0; a < 3; ++a) {
      moved[a] = joint.anchor[a];
      for (unsigned b = 0; b < 3; ++b) moved[a] -= R(a, b) * joint.anchor[b];
    }
  }
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b) origin[a] += relative.matrix(a, b) * moved[b];
  // a moving matrix, not a product: the frame recursion takes its angular velocity from the whole
  relative.sequence.clear();
  relative.matrix = relative.matrix.mul(R);
  return joint;
}

}  // namespace eomgen
