/// @file Joints read from a frame's rotation when it is written as a product: a frame placed by
/// rotation = "rot_x(-Pi/2)*rot_z(q2)" and a constant origin is a revolute joint about z, placed
/// by rot_x(−Pi/2), as if it had joint = { type = "revolute", axis = [0, 0, 1], coordinate = "q2" }.
/// So a tree written with rotations is the same tree as one written with joints, and takes the
/// spatial algorithms (generator/spatial/) without a key to set.
///
/// The product R = F_1 F_2 ⋯ F_k may hold several factors in coordinates (a universal joint,
/// rot_z(a)*rot_x(b)): each ends a link, R_p R_e(m q + c) with R_p the constant factors before it,
/// as build_joints.cpp moves a frame by a joint; the links before the last are massless frames of
/// their own, and constant factors after the last coordinate's make a fixed link that carries the
/// frame's name.
#pragma once

#include <optional>
#include <vector>

#include "model/model.hpp"

namespace eomgen {

/// One link of a frame read as joints: its rotation in the link above (a product), its origin
/// there, and its joint (placement R_p and origin, axis, coordinate, multiplier and offset).
struct JointLink {
  Rotation relative;
  Vector3 origin{0, 0, 0};
  FrameLink::Joint joint;
};

/// The links of a frame whose rotation is a product of constant turns and turns by m·q + c
/// about constant axes (q a coordinate; m ≠ 0 and c constants) and whose origin is constant, the
/// frame's own the last; nothing when it is not one (a matrix, an angle in t or in several
/// coordinates, an origin that moves, or no coordinate at all).
std::optional<std::vector<JointLink>> frame_as_joints(const Rotation& rotation, const Vector3& origin,
                                                      const Symbols& symbols);

}  // namespace eomgen
