/// @file What the import reads off MuJoCo's compiled model in more than one place: names, joints of
/// one velocity, a joint's place among its body's, fixed tendons.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "import/robot.hpp"

namespace eomgen {

/// Element i's name from `addresses` (m->name_jntadr, ...), "" where the model keeps none.
std::string name_of(const mjModel* m, const int* addresses, int i);

/// Whether joint j is a hinge or a slide (one velocity).
bool one_dof_joint(const mjModel* m, int j);

/// Joint j of the model as a body's index, the joint's place among that body's joints, and its qpos0.
void place_joint(const mjModel* m, int j, int& body, int& joint, double& reference);

/// Tendon t's joints and coefficients where it is fixed (MJCF's <fixed>: every wrap a hinge or
/// slide), or nothing.
std::optional<std::vector<TendonJoint>> fixed_tendon(const mjModel* m, int t);

/// The first four names, quoted, and how many more.
std::string listed(const std::vector<std::string>& names);

}  // namespace eomgen
