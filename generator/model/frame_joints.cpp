#include "model/frame_joints.hpp"

#include "model/frames.hpp"
#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

bool is_constant(const ex& x, const Symbols& s) {
  if (x.has(s.time)) return false;
  for (const auto* list : {&s.coordinates, &s.velocities, &s.inputs})
    for (const GiNaC::realsymbol& y : *list)
      if (x.has(y)) return false;
  return true;
}

// m·q + c in one coordinate q, m and c constants, m ≠ 0 at the parameters' defaults: its
// coordinate's index with m and c, or nothing (a constant angle gives index −1)
struct LinearAngle {
  int coordinate = -1;
  ex multiplier = 0, offset = 0;
};
std::optional<LinearAngle> linear_angle(const ex& angle, const Symbols& s) {
  if (is_constant(angle, s)) return LinearAngle{-1, 0, angle};
  ex a = angle.expand();
  for (std::size_t i = 0; i < s.coordinates.size(); ++i) {
    const GiNaC::realsymbol& q = s.coordinates[i];
    if (!a.has(q)) continue;
    if (a.degree(q) != 1 || a.ldegree(q) < 0) return std::nullopt;
    LinearAngle l{int(i), a.coeff(q, 1), a.coeff(q, 0)};
    auto m = constant_value(l.multiplier, s);
    if (!is_constant(l.multiplier, s) || !is_constant(l.offset, s) || !m || *m == 0) return std::nullopt;
    return l;
  }
  return std::nullopt;
}

GiNaC::matrix product(const std::vector<ElementaryRotation>& factors) {
  GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  for (const ElementaryRotation& f : factors) R = R.mul(rotation_matrix(f));
  return R;
}

// the link that the factors before a turn by m·q + c and that turn make: R_p R_e(m q + c)
JointLink turned_link(const std::vector<ElementaryRotation>& placement, const ElementaryRotation& turn,
                      const LinearAngle& angle, const Vector3& origin) {
  JointLink link;
  link.relative.sequence = placement;
  link.relative.sequence.push_back(turn);
  link.relative.matrix = product(link.relative.sequence);
  link.origin = origin;
  FrameLink::Joint& j = link.joint;
  j.type = FrameLink::Joint::Type::revolute;
  j.coordinate = angle.coordinate;
  j.multiplier = angle.multiplier;
  j.offset = angle.offset;
  j.axis = rotation_axis(turn);
  j.placement = product(placement);
  j.placement_origin = origin;
  return link;
}

}  // namespace

std::optional<std::vector<JointLink>> frame_as_joints(const Rotation& rotation, const Vector3& origin,
                                                      const Symbols& symbols) {
  if (rotation.sequence.empty()) return std::nullopt;
  for (const ex& x : origin)
    if (!is_constant(x, symbols)) return std::nullopt;
  std::vector<JointLink> links;
  std::vector<ElementaryRotation> placement;
  for (const ElementaryRotation& factor : rotation.sequence) {
    if (factor.axis == ElementaryRotation::constant_matrix) {
      if (!is_constant(ex(factor.constant), symbols)) return std::nullopt;
      placement.push_back(factor);
      continue;
    }
    auto angle = linear_angle(factor.angle, symbols);
    if (!angle) return std::nullopt;
    if (angle->coordinate < 0) {
      placement.push_back(factor);
      continue;
    }
    // the first link sits at the frame's origin, the next at the origin of the one before
    links.push_back(turned_link(placement, factor, *angle, links.empty() ? origin : Vector3{0, 0, 0}));
    placement.clear();
  }
  if (links.empty()) return std::nullopt;
  if (!placement.empty()) {
    JointLink fixed;
    fixed.relative.sequence = placement;
    fixed.relative.matrix = product(placement);
    fixed.joint.placement = fixed.relative.matrix;
    links.push_back(fixed);
  }
  return links;
}

}  // namespace eomgen
