/// @file Joints read from a frame's placement when it is written as products and sums: a frame
/// placed by rotation = "rot_x(-Pi/2)*rot_z(q2)" and a constant origin is a revolute joint about
/// z, placed by rot_x(−Pi/2), as if it had joint = { type = "revolute", axis = [0, 0, 1],
/// coordinate = "q2" }, and one whose origin is ["x", "0", "h"] slides along x by x. So a tree
/// written with rotations and moving origins is the same tree as one written with joints, and
/// takes the spatial algorithms (generator/spatial/) without a key to set.
///
/// The origin c + Σ v_k q_k (in the parent's axes) gives a prismatic joint per coordinate, along
/// v_k, and the rotation R = F_1 F_2 ⋯ F_n then a revolute joint per factor in a coordinate: each
/// ends a link, R_p R_e(m q + c) with R_p the constant factors before it, as build_joints.cpp
/// moves a frame by a joint. All links but the last are massless frames of their own (a gantry's
/// slides, a universal joint's first turn), and constant factors after the last coordinate's make
/// a fixed link that carries the frame's name.
#pragma once

#include <optional>
#include <vector>

#include "model/model.hpp"

namespace eomgen {

/// One link of a frame read as joints: its rotation in the link above (a product), its origin
/// there (in the coordinates, for a slide), and its joint (placement R_p and origin at the joint's
/// zero, axis, coordinate, multiplier and offset).
struct JointLink {
  Rotation relative;
  Vector3 origin{0, 0, 0};
  FrameLink::Joint joint;
};

/// The links of a frame whose rotation is a product of constant turns and turns by m·q + c
/// about constant axes (q a coordinate; m ≠ 0 and c constants), or a constant matrix, and whose
/// origin is c + Σ v_k q_k (v_k along a coordinate axis, or numbers), the frame's own the last;
/// nothing when it is not one (a matrix that moves, an angle in t or in several coordinates or
/// not linear, an origin that is not linear in q or moves with t, or no coordinate at all).
std::optional<std::vector<JointLink>> frame_as_joints(const Rotation& rotation, const Vector3& origin,
                                                      const Symbols& symbols);

}  // namespace eomgen
