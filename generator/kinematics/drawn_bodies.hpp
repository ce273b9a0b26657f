/// @file The bodies `eomgen animate` draws, as the header's body_poses gives them: the model's
/// frames, particles, rigid bodies and points, each joined to its parent: the frame it is placed
/// in, or, in a tree of particles, the particle it hangs from.
#pragma once

#include <functional>
#include <vector>

#include "model/model.hpp"

namespace eomgen {

/// The model's drawing, with the parents a tree of particles gives to the particles outside frames.
std::vector<DrawnBody> drawn_bodies(const Model& model);

/// Removes the bodies for which `gone` holds; their children hang from the ground then.
void remove_drawn_bodies(std::vector<DrawnBody>& drawing, const std::function<bool(const DrawnBody&)>& gone);

}  // namespace eomgen
