/// @file Three-vectors of expressions: the few operations the kinematics' recursions use.
#pragma once

#include "model/model.hpp"

namespace eomgen {

inline Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline GiNaC::ex dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline Vector3 column(const GiNaC::matrix& m, unsigned j) { return {m(0, j), m(1, j), m(2, j)}; }

/// R·x, or Rᵀ·x
inline Vector3 times(const GiNaC::matrix& R, const Vector3& x, bool transposed = false) {
  Vector3 y{0, 0, 0};
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b) y[a] += (transposed ? R(b, a) : R(a, b)) * x[b];
  return y;
}

inline Vector3 operator+(const Vector3& a, const Vector3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vector3 operator-(const Vector3& a, const Vector3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vector3 scaled(const GiNaC::ex& s, const Vector3& a) { return {s * a[0], s * a[1], s * a[2]}; }

/// Euler's moment I α + ω × I ω, in body components.
inline Vector3 euler_moment(const GiNaC::matrix& I, const Vector3& w, const Vector3& alpha) {
  return times(I, alpha) + cross(w, times(I, w));
}

}  // namespace eomgen
