/// @file Frames for recursive kinematics (a tree of joints, or a deep chain of frames composed link
/// by link: build_model() chooses): each frame's
/// rotation to inertial components and its inertial origin are quantities of their own,
/// R = R_parent·R_rel and o = o_parent + R_parent·o_rel (Hiller §3.9), instead of being
/// multiplied out in the coordinates. Multiplied out, the entries of a chain of n rotations
/// have up to 4ⁿ terms; as intermediates each costs a few products of its parent's.
#pragma once

#include <string>

#include "model/frames.hpp"
#include "model/model.hpp"

namespace eomgen {

/// `definition` itself when it is a constant, or a symbol or the sine or cosine of one or the
/// negative of either, otherwise a new intermediate of `model` named `name` (printed) and `cpp_name` (in
/// generated code).
GiNaC::ex intermediate(std::vector<Intermediate>& intermediates, const std::string& name, const std::string& cpp_name,
                       const GiNaC::ex& definition);
/// intermediate() of `definition` expanded, printed WHO.LABEL and named k_WHO_LABEL in C++ (a dot
/// in WHO becomes _): a frame's or link's quantity.
GiNaC::ex named_intermediate(std::vector<Intermediate>& intermediates, const std::string& who, const std::string& label,
                             const GiNaC::ex& definition);

/// Adds the frame `name` in `parent` (an index into model.frame_links, -1 for the inertial
/// frame) to the model's frame links, and returns it placed in its intermediates.
PlacedFrame place_recursive_frame(Model& model, const std::string& name, int parent, const Rotation& relative,
                                  const Vector3& origin);

/// Whether a placement (rotation and origin) depends on time itself: recursive kinematics
/// takes placements that the coordinates alone move.
bool moves_with_time(const GiNaC::matrix& rotation, const Vector3& origin, const GiNaC::ex& time);

/// Whether a vector contains one of the intermediates (a frame's rotation or origin).
bool uses_frames(const Vector3& v, const std::vector<Intermediate>& intermediates);

}  // namespace eomgen
