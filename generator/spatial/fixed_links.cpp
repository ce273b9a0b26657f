#include "spatial/fixed_links.hpp"

#include "kinematics/vector3.hpp"

namespace eomgen {

namespace {

GiNaC::matrix expanded_entries(const GiNaC::matrix& m) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned r = 0; r < m.rows(); ++r)
    for (unsigned c = 0; c < m.cols(); ++c) out(r, c) = m(r, c).expand();
  return out;
}

Vector3 expanded_entries(const Vector3& x) { return {x[0].expand(), x[1].expand(), x[2].expand()}; }

}  // namespace

TreeLink::Body body_in(const TreeLink::Body& body, const GiNaC::matrix& turn, const Vector3& offset) {
  return {body.mass, expanded_entries(offset + times(turn, body.center)),
          expanded_entries(turn.mul(body.inertia).mul(turn.transpose()))};
}

std::vector<TreeLink::Body> as_one_body(const std::vector<TreeLink::Body>& bodies) {
  if (bodies.size() < 2) return bodies;
  GiNaC::ex mass = 0;
  for (const TreeLink::Body& b : bodies) {
    bool known = GiNaC::is_a<GiNaC::numeric>(b.mass);
    for (unsigned a = 0; a < 3; ++a) {
      known = known && GiNaC::is_a<GiNaC::numeric>(b.center[a]);
      for (unsigned c = 0; c < 3; ++c) known = known && GiNaC::is_a<GiNaC::numeric>(b.inertia(a, c));
    }
    if (!known) return bodies;
    mass += b.mass;
  }
  if (mass.is_zero()) return bodies;
  Vector3 center{0, 0, 0};
  for (const TreeLink::Body& b : bodies) center = center + scaled(b.mass / mass, b.center);
  GiNaC::matrix inertia(3, 3);
  for (const TreeLink::Body& b : bodies) {
    Vector3 d = b.center - center;
    GiNaC::ex dd = dot(d, d);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned c = 0; c < 3; ++c) inertia(a, c) += b.inertia(a, c) + b.mass * ((a == c ? dd : GiNaC::ex(0)) - d[a] * d[c]);
  }
  return {TreeLink::Body{mass, expanded_entries(center), expanded_entries(inertia)}};
}

}  // namespace eomgen
