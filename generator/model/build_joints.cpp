// A frame's joint (FrameEntry::joint): MJCF's hinge and slide. The frame is first placed by
// its rotation R_p and origin o_p; a revolute joint then turns it by q about the unit axis e
// through the anchor a (both in the frame's own coordinates), a prismatic joint slides it
// by q along e:
//   revolute:  R = R_p·R_e(q),  o = o_p + R_p·(a − R_e(q)·a)
//   prismatic: R = R_p,         o = o_p + R_p·e·q
// so that the anchor stays where it is and q = 0 is the placement. A joint that follows a
// coordinate (a mimic) moves by m·q + c in place of q.
#include <fmt/format.h>

#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

bool moves_with(const ex& x, const Symbols& s) {
  if (x.has(s.time)) return true;
  for (const GiNaC::realsymbol& q : s.coordinates)
    if (x.has(q)) return true;
  return false;
}

bool moves_with(const GiNaC::matrix& R, const Symbols& s) {
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      if (moves_with(R(i, j), s)) return true;
  return false;
}

std::optional<ex> ModelBuilder::joint_coordinate(const JointEntry& j) {
  const Symbols& s = m_.symbols;
  for (std::size_t i = 0; i < s.coordinate_names.size(); ++i)
    if (s.coordinate_names[i] == j.coordinate) return ex(s.coordinates[i]);
  d_.error(j.coordinate_where, j.key + ".coordinate", fmt::format("'{}' is not a coordinate", j.coordinate),
           s.coordinate_names.empty() ? "declare it under [coordinates]" : suggest(j.coordinate, s.coordinate_names, "coordinates"));
  return std::nullopt;
}

std::optional<Vector3> ModelBuilder::joint_axis(const JointEntry& j) {
  Vector3 e = vector(j.axis, allow_parameters, "a joint axis");
  auto length = constant_value((e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).subs(m_.symbols.default_parameter_values()),
                               m_.symbols);
  if (!length || *length <= 0) {
    d_.error(j.axis[0].where, j.key + ".axis", "the joint's axis is zero", "give its direction, e.g. [0, 0, 1]");
    return std::nullopt;
  }
  return e;
}

// a joint that follows a coordinate (URDF's mimic): multiplier and offset constants, the
// multiplier not zero (such a joint would not move: a fixed one)
bool ModelBuilder::follow(const JointEntry& j, FrameLink::Joint& joint) {
  bool valid = true;
  auto constant = [&](const std::optional<ExpressionText>& text, ex& out, bool nonzero) {
    if (!text) return;
    auto e = parse(*text, allow_parameters, "a joint's multiplier or offset");
    if (!e) {
      valid = false;
      return;
    }
    auto value = constant_value(e->subs(m_.symbols.default_parameter_values()), m_.symbols);
    if (!value || (nonzero && *value == 0)) {
      d_.error(text->where, text->key, value ? "the multiplier is zero: the joint would not move" : "it is not a constant",
               value ? "use type = \"fixed\" for a joint that does not move" : "give a number or an expression of parameters");
      valid = false;
      return;
    }
    out = *e;
  };
  constant(j.multiplier, joint.multiplier, true);
  constant(j.offset, joint.offset, false);
  return valid;
}

std::optional<FrameLink::Joint> ModelBuilder::move_by_joint(const JointEntry& j, Rotation& relative, Vector3& origin) {
  FrameLink::Joint joint;
  if (j.type == "fixed") return joint;
  if (j.type == "ball" || j.type == "free") return turn_by_quaternion(j, relative, origin);
  if (j.type.empty() || j.axis.size() != 3) return std::nullopt;  // reported by the parser
  auto q = joint_coordinate(j);
  auto axis = joint_axis(j);
  if (!q || !axis || !follow(j, joint)) return std::nullopt;
  for (std::size_t i = 0; i < m_.symbols.coordinates.size(); ++i)
    if (q->is_equal(m_.symbols.coordinates[i])) joint.coordinate = int(i);
  q = joint.multiplier * *q + joint.offset;
  joint.axis = unit_direction(*axis);
  ElementaryRotation turn = turn_about(*axis, *q);
  joint.type = j.type == "prismatic" ? FrameLink::Joint::Type::prismatic : FrameLink::Joint::Type::revolute;
  if (j.type == "prismatic") {
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) origin[a] += relative.matrix(a, b) * joint.axis[b] * *q;
    return joint;
  }
  GiNaC::matrix R = rotation_matrix(turn);
  if (!j.anchor.empty()) {
    Vector3 anchor = vector(j.anchor, allow_parameters, "a joint anchor");
    joint.anchor = anchor;
    for (unsigned a = 0; a < 3; ++a) {
      ex moved = anchor[a];
      for (unsigned b = 0; b < 3; ++b) moved -= R(a, b) * anchor[b];
      for (unsigned c = 0; c < 3; ++c) origin[c] += relative.matrix(c, a) * moved;
    }
  }
  if (!is_product(relative)) {
    if (moves_with(relative.matrix, m_.symbols)) {
      relative.matrix = relative.matrix.mul(R);  // a moving matrix: the angular velocity comes from the whole
      return joint;
    }
    ElementaryRotation placement{ElementaryRotation::constant_matrix, 0};
    placement.constant = relative.matrix;
    relative.sequence = {placement};
  }
  relative.sequence.push_back(turn);
  relative.matrix = relative.matrix.mul(R);
  return joint;
}

bool ModelBuilder::is_constant_placement(const Rotation& rotation, const Vector3& origin) const {
  if (moves_with(rotation.matrix, m_.symbols)) return false;
  for (const ex& x : origin)
    if (moves_with(x, m_.symbols)) return false;
  return true;
}

}  // namespace eomgen
