/// @file Frames placed in their parents ([[frames]]), resolved into inertial terms in
/// file order: R = R_parent·R_rel and o = o_parent + R_parent·o_rel. A chain of rotations
/// written as products stays one product, so the angular velocity composes along it
/// (Hiller §3.9: ω of a child = ω of the parent + the relative one) instead of being
/// differentiated out of the full matrix.
#pragma once

#include "model/model.hpp"

namespace eomgen {

/// A frame in inertial terms.
struct PlacedFrame {
  Rotation rotation;   // body components to inertial
  Vector3 origin{0, 0, 0};
};

/// The inertial frame itself.
PlacedFrame inertial_frame();

/// A rotation given as a product has its elementary rotations; one given as a matrix does not.
bool is_product(const Rotation& r);

/// parent·relative, as one product when both are products.
Rotation compose(const Rotation& parent, const Rotation& relative);

/// The child frame of `parent` rotated by `relative` with its origin at `origin` (parent coordinates).
PlacedFrame place_frame(const PlacedFrame& parent, const Rotation& relative, const Vector3& origin);

/// Inertial position of the point with coordinates `local` in the frame.
Vector3 place_point(const PlacedFrame& frame, const Vector3& local);

}  // namespace eomgen
