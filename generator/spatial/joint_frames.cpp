#include "spatial/joint_frames.hpp"

#include <algorithm>
#include <cstddef>

#include <cln/real.h>

#include "kinematics/vector3.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// 40 digits, against the 34 of the widest scalar a header is instantiated with (__float128)
class WorkingDigits {
 public:
  WorkingDigits() : saved_(GiNaC::Digits) { GiNaC::Digits = 40; }
  ~WorkingDigits() { GiNaC::Digits = saved_; }
  WorkingDigits(const WorkingDigits&) = delete;
  WorkingDigits& operator=(const WorkingDigits&) = delete;

 private:
  long saved_;
};

bool is_number(const ex& x) { return GiNaC::is_a<numeric>(x.evalf()); }

numeric value_of(const ex& x) { return GiNaC::ex_to<numeric>(x.evalf()); }

// the one axis k that e lies along (e = ±e_k), or −1
int coordinate_axis(const Vector3& e) {
  int along = -1;
  for (int k = 0; k < 3; ++k) {
    if (e[std::size_t(k)].is_zero()) continue;
    if (along >= 0) return -1;
    along = k;
  }
  return along;
}

GiNaC::matrix axes_of(const Vector3& x, const Vector3& y, const Vector3& z) {
  GiNaC::matrix C(3, 3);
  for (unsigned a = 0; a < 3; ++a) {
    C(a, 0) = x[a];
    C(a, 1) = y[a];
    C(a, 2) = z[a];
  }
  return C;
}

Vector3 unit(const Vector3& v) {
  numeric length = GiNaC::sqrt(value_of(dot(v, v)));
  return {value_of(v[0]) / length, value_of(v[1]) / length, value_of(v[2]) / length};
}

numeric nearest_integer(const numeric& x) {
  return numeric(cln::cl_N(cln::floor1(cln::the<cln::cl_R>((x + numeric(1, 2)).to_cl_N()))));
}

// the nearest multiple of 10^-36: a number of the axes made exact, so that all that follows is
// exact rational arithmetic, whose results do not depend on the order GiNaC adds terms in
ex exact_entry(const ex& x) {
  static const numeric unit = numeric(10).power(36);
  numeric scaled = value_of(x) * unit;
  return nearest_integer(scaled) / unit;
}

// right-handed axes with z = e: a signed permutation for e = ±e_k (x' = e_{k+1}, y' = z' × x'),
// else x' normal to e and to the coordinate axis e is least along
JointFrame axes_along(const Vector3& e) {
  JointFrame f;
  Vector3 x{0, 0, 0};
  if (int k = coordinate_axis(e); k >= 0) {
    x[std::size_t((k + 1) % 3)] = 1;
    f.axes = axes_of(x, cross(e, x), e);
    return f;
  }
  WorkingDigits digits;
  Vector3 z = unit(e);
  std::size_t least = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (GiNaC::abs(GiNaC::ex_to<numeric>(z[k])) < GiNaC::abs(GiNaC::ex_to<numeric>(z[least]))) least = k;
  Vector3 a{0, 0, 0};
  a[least] = 1;
  x = unit(cross(a, z));
  Vector3 y = cross(z, x);
  for (Vector3* v : {&x, &y, &z})
    for (ex& c : *v) c = exact_entry(c);
  f.axes = axes_of(x, y, z);
  f.floating = true;
  return f;
}

}  // namespace

JointFrame joint_frame(const FrameLink::Joint& joint) {
  using Type = FrameLink::Joint::Type;
  JointFrame f;
  f.axes = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  bool numeric_axis = is_number(joint.axis[0]) && is_number(joint.axis[1]) && is_number(joint.axis[2]);
  if ((joint.type == Type::revolute || joint.type == Type::prismatic) && numeric_axis) f = axes_along(joint.axis);
  if (joint.type == Type::ball || (joint.type == Type::revolute && numeric_axis)) f.origin = joint.anchor;
  return f;
}

ex without_rounding_residue(const ex& x, const ex& scale) {
  if (!GiNaC::is_a<numeric>(x) || !GiNaC::is_a<numeric>(scale)) return x;
  return GiNaC::abs(GiNaC::ex_to<numeric>(x)) < GiNaC::abs(GiNaC::ex_to<numeric>(scale)) * numeric(10).power(-30) ? ex(0) : x;
}

namespace {

numeric coefficient(const ex& term) {
  if (GiNaC::is_a<numeric>(term)) return GiNaC::ex_to<numeric>(term);
  if (GiNaC::is_a<GiNaC::mul>(term)) {
    ex last = term.op(term.nops() - 1);
    if (GiNaC::is_a<numeric>(last)) return GiNaC::ex_to<numeric>(last);
  }
  return 1;
}

}  // namespace

ex without_small_terms(const ex& x) {
  if (!GiNaC::is_a<GiNaC::add>(x)) return x;
  numeric largest = 0;
  for (const ex& term : x) largest = std::max(largest, GiNaC::abs(coefficient(term)));
  numeric limit = largest * numeric(10).power(-30);
  ex kept = 0;
  for (const ex& term : x)
    if (GiNaC::abs(coefficient(term)) >= limit) kept += term;
  return kept;
}

ex rotation_entry(const ex& x, bool approximate) {
  if (!is_number(x) || (GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_rational() && !approximate)) return x;
  WorkingDigits digits;
  ex value = value_of(x);
  for (int target : {0, 1, -1})
    if (without_rounding_residue(value - target, 1).is_zero()) return target;
  return exact_entry(value);
}

ex rounded_to(const ex& x, const ex& scale) {
  if (!GiNaC::is_a<numeric>(x) || !GiNaC::is_a<numeric>(scale) || scale.is_zero()) return x;
  numeric unit = 1, size = GiNaC::abs(GiNaC::ex_to<numeric>(scale));
  while (unit > size) unit /= 10;
  while (unit * 10 <= size) unit *= 10;
  unit *= numeric(10).power(-36);
  return nearest_integer(GiNaC::ex_to<numeric>(x) / unit) * unit;
}

}  // namespace eomgen
