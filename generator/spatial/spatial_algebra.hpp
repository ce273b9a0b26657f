/// @file The 6-D motion and force algebra of the spatial algorithms, over GiNaC expressions: a
/// spatial vector in Plücker coordinates about one origin, its two cross products (Featherstone's
/// × for motions and ×* for forces), the power of a motion against a force, and a rigid body's
/// spatial inertia applied to a twist. In namespace eomgen beside Vector3's algebra
/// (kinematics/vector3.hpp), so that each overload is found wherever both are used.
#pragma once

#include <ginac/ginac.h>

#include "kinematics/vector3.hpp"

namespace eomgen {

/// A motion (ω; v_O) or a force (n_O; f), about the origin O of the coordinates they are written in.
struct SpatialVector {
  Vector3 top{0, 0, 0}, bottom{0, 0, 0};
  const GiNaC::ex& operator[](unsigned k) const { return k < 3 ? top[k] : bottom[k - 3]; }
};

inline SpatialVector operator+(const SpatialVector& a, const SpatialVector& b) {
  return {a.top + b.top, a.bottom + b.bottom};
}

inline SpatialVector scaled(const GiNaC::ex& s, const SpatialVector& a) { return {scaled(s, a.top), scaled(s, a.bottom)}; }

/// m × x for a motion x: how x changes seen from a frame moving with the twist m
inline SpatialVector motion_cross(const SpatialVector& m, const SpatialVector& x) {
  return {cross(m.top, x.top), cross(m.top, x.bottom) + cross(m.bottom, x.top)};
}

/// m ×* f for a force f
inline SpatialVector force_cross(const SpatialVector& m, const SpatialVector& f) {
  return {cross(m.top, f.top) + cross(m.bottom, f.bottom), cross(m.top, f.bottom)};
}

/// the components' dot product: a motion's power against a force
inline GiNaC::ex power(const SpatialVector& m, const SpatialVector& f) { return dot(m.top, f.top) + dot(m.bottom, f.bottom); }

/// mass, first moment h = m c and inertia J about the origin O
struct SpatialInertia {
  GiNaC::ex mass = 0;
  Vector3 first{0, 0, 0};
  GiNaC::matrix J{3, 3};
};

/// the momentum of the twist x: (J ω + h × v; m v − h × ω)
inline SpatialVector apply(const SpatialInertia& I, const SpatialVector& x) {
  return {times(I.J, x.top) + cross(I.first, x.bottom), scaled(I.mass, x.bottom) - cross(I.first, x.top)};
}

/// B x (or Bᵀ x) for a 6×6 matrix B
inline SpatialVector times(const GiNaC::matrix& B, const SpatialVector& x, bool transposed = false) {
  SpatialVector y;
  for (unsigned r = 0; r < 6; ++r) {
    GiNaC::ex sum = 0;
    for (unsigned c = 0; c < 6; ++c) sum += (transposed ? B(c, r) : B(r, c)) * x[c];
    (r < 3 ? y.top[r] : y.bottom[r - 3]) = sum;
  }
  return y;
}

}  // namespace eomgen
