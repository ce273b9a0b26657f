#include "model/frame_joints.hpp"

#include "model/frames.hpp"
#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// a placement is parsed in the parameters, the coordinates and t alone
bool is_constant(const ex& x, const Symbols& s) { return !moves_with(x, s); }

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

// the link that the factors before a turn by m·q + c and that turn make: R_p R_e(m q + c)
JointLink turned_link(const std::vector<ElementaryRotation>& placement, const ElementaryRotation& turn,
                      const LinearAngle& angle, const Vector3& origin) {
  JointLink link;
  link.relative.sequence = placement;
  link.relative.sequence.push_back(turn);
  link.relative.matrix = rotation_product(link.relative.sequence);
  link.origin = origin;
  FrameLink::Joint& j = link.joint;
  j.type = FrameLink::Joint::Type::revolute;
  j.coordinate = angle.coordinate;
  j.multiplier = angle.multiplier;
  j.offset = angle.offset;
  j.axis = rotation_axis(turn);
  j.placement = rotation_product(placement);
  j.placement_origin = origin;
  return link;
}

// the origin c + Σ v_k q_k, c and each v_k constant: c and, in the coordinates' order, each slide
// along the unit e_k by m_k q_k (v_k = m_k e_k: e_k a coordinate axis and m_k that entry, or, for a
// vector of numbers, e_k = v_k/|v_k| and m_k = |v_k|); nothing when it is not so
struct SlidingOrigin {
  Vector3 constant{0, 0, 0};
  struct Slide {
    int coordinate;
    Vector3 axis;
    ex multiplier;
  };
  std::vector<Slide> slides;
};
std::optional<SlidingOrigin> sliding_origin(const Vector3& origin, const Symbols& s) {
  SlidingOrigin o;
  std::vector<Vector3> along(s.coordinates.size(), Vector3{0, 0, 0});
  for (unsigned a = 0; a < 3; ++a) {
    ex rest = origin[a].expand();
    for (std::size_t i = 0; i < s.coordinates.size(); ++i) {
      const GiNaC::realsymbol& q = s.coordinates[i];
      if (!rest.has(q)) continue;
      if (rest.degree(q) != 1 || rest.ldegree(q) < 0 || !is_constant(rest.coeff(q, 1), s)) return std::nullopt;
      along[i][a] = rest.coeff(q, 1);
      rest = rest.coeff(q, 0);
    }
    if (!is_constant(rest, s)) return std::nullopt;
    o.constant[a] = rest;
  }
  for (std::size_t i = 0; i < along.size(); ++i) {
    const Vector3& v = along[i];
    int entries = int(!v[0].is_zero()) + int(!v[1].is_zero()) + int(!v[2].is_zero());
    if (entries == 0) continue;
    SlidingOrigin::Slide slide{int(i), Vector3{0, 0, 0}, 0};
    if (entries == 1) {
      unsigned k = !v[0].is_zero() ? 0 : !v[1].is_zero() ? 1 : 2;
      slide.axis[k] = 1;
      slide.multiplier = v[k];
    } else {
      for (const ex& x : v)
        if (!GiNaC::is_a<GiNaC::numeric>(x)) return std::nullopt;
      slide.multiplier = GiNaC::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (unsigned k = 0; k < 3; ++k) slide.axis[k] = v[k] / slide.multiplier;
    }
    auto m = constant_value(slide.multiplier, s);
    if (!m || *m == 0) return std::nullopt;
    o.slides.push_back(slide);
  }
  return o;
}

// a massless link slid by m q along e from `at` (the frame's constant origin, or zero after it)
JointLink slid_link(const SlidingOrigin::Slide& slide, const Vector3& at, const Symbols& s) {
  JointLink link;
  link.relative.matrix = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  ex q = slide.multiplier * s.coordinates[std::size_t(slide.coordinate)];
  for (unsigned a = 0; a < 3; ++a) link.origin[a] = at[a] + slide.axis[a] * q;
  FrameLink::Joint& j = link.joint;
  j.type = FrameLink::Joint::Type::prismatic;
  j.coordinate = slide.coordinate;
  j.multiplier = slide.multiplier;
  j.axis = slide.axis;
  j.placement = link.relative.matrix;
  j.placement_origin = at;
  return link;
}

// the rotation's factors: its product, or a constant matrix as one factor; nothing for a matrix that moves
std::optional<std::vector<ElementaryRotation>> rotation_factors(const Rotation& rotation, const Symbols& s) {
  if (is_product(rotation)) return rotation.sequence;
  if (moves_with(rotation.matrix, s)) return std::nullopt;
  ElementaryRotation whole{ElementaryRotation::constant_matrix, 0};
  whole.constant = rotation.matrix;
  return std::vector<ElementaryRotation>{whole};
}

}  // namespace

std::optional<std::vector<JointLink>> frame_as_joints(const Rotation& rotation, const Vector3& origin,
                                                      const Symbols& symbols) {
  auto factors = rotation_factors(rotation, symbols);
  auto offset = sliding_origin(origin, symbols);
  if (!factors || !offset) return std::nullopt;
  // translations first, in the parent's axes, then the turns: o(q) is in the parent's coordinates
  std::vector<JointLink> links;
  const Vector3 zero{0, 0, 0};
  for (const SlidingOrigin::Slide& slide : offset->slides)
    links.push_back(slid_link(slide, links.empty() ? offset->constant : zero, symbols));
  std::vector<ElementaryRotation> placement;
  for (const ElementaryRotation& factor : *factors) {
    if (factor.axis == ElementaryRotation::constant_matrix) {
      if (moves_with(factor.constant, symbols)) return std::nullopt;
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
    links.push_back(turned_link(placement, factor, *angle, links.empty() ? offset->constant : zero));
    placement.clear();
  }
  if (links.empty()) return std::nullopt;
  if (!placement.empty()) {
    JointLink fixed;
    fixed.relative.sequence = placement;
    fixed.relative.matrix = rotation_product(placement);
    fixed.joint.placement = fixed.relative.matrix;
    links.push_back(fixed);
  }
  return links;
}

}  // namespace eomgen
