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
