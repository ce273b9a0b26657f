#include "model/frames.hpp"

namespace eomgen {

using GiNaC::ex;

GiNaC::matrix elementary_rotation(int axis, const ex& a) {
  ex c = GiNaC::cos(a), s = GiNaC::sin(a);
  switch (axis) {
    case 0: return GiNaC::matrix(3, 3, GiNaC::lst{1, 0, 0, 0, c, -s, 0, s, c});
    case 1: return GiNaC::matrix(3, 3, GiNaC::lst{c, 0, s, 0, 1, 0, -s, 0, c});
    default: return GiNaC::matrix(3, 3, GiNaC::lst{c, -s, 0, s, c, 0, 0, 0, 1});
  }
}

GiNaC::matrix rotation_matrix(const ElementaryRotation& r) {
  if (r.axis == ElementaryRotation::constant_matrix) return r.constant;
  if (r.axis != ElementaryRotation::about_direction) return elementary_rotation(r.axis, r.angle);
  ex c = GiNaC::cos(r.angle), s = GiNaC::sin(r.angle);
  const auto& e = r.direction;
  GiNaC::matrix R(3, 3);
  const ex cross[3][3] = {{0, -e[2], e[1]}, {e[2], 0, -e[0]}, {-e[1], e[0], 0}};
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b) R(a, b) = (a == b ? c : ex(0)) + s * cross[a][b] + (1 - c) * e[a] * e[b];
  return R;
}

GiNaC::matrix rotation_product(const std::vector<ElementaryRotation>& factors) {
  GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  for (const ElementaryRotation& f : factors) R = R.mul(rotation_matrix(f));
  return R;
}

Vector3 rotation_axis(const ElementaryRotation& r) {
  if (r.axis == ElementaryRotation::constant_matrix) return {0, 0, 0};
  if (r.axis == ElementaryRotation::about_direction) return r.direction;
  Vector3 e{0, 0, 0};
  e[std::size_t(r.axis)] = 1;
  return e;
}

PlacedFrame inertial_frame() {
  PlacedFrame f;
  f.rotation.matrix = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  return f;
}

bool is_product(const Rotation& r) {
  return !r.sequence.empty() || ex(r.matrix).is_equal(GiNaC::unit_matrix(3));
}

Rotation compose(const Rotation& parent, const Rotation& relative) {
  Rotation r;
  r.matrix = parent.matrix.mul(relative.matrix);
  if (is_product(parent) && is_product(relative)) {
    r.sequence = parent.sequence;
    r.sequence.insert(r.sequence.end(), relative.sequence.begin(), relative.sequence.end());
  }
  return r;
}

Vector3 place_point(const PlacedFrame& frame, const Vector3& local) {
  Vector3 r = frame.origin;
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b)
      if (!local[b].is_zero()) r[a] += frame.rotation.matrix(a, b) * local[b];
  return r;
}

PlacedFrame place_frame(const PlacedFrame& parent, const Rotation& relative, const Vector3& origin) {
  return {compose(parent.rotation, relative), place_point(parent, origin)};
}

}  // namespace eomgen
