/// @file Inertias that break the triangle inequality of principal moments, A + B ≥ C. A rigid body's
/// cannot, yet URDF files often carry such values (a dummy link's `ixx = ixy = … = 1e-6`, rounded
/// CAD output), and URDF readers such as Pinocchio's take them as written. MuJoCo's compiler refuses
/// them ("inertia must satisfy A + B >= C"); with its `balanceinertia` it replaces each by the mean
/// of its three moments, which changes the dynamics. So a URDF it refuses is read again with
/// `balanceinertia`, and each body MuJoCo balanced is given back the inertia its link's <inertial>
/// states. So is every other body that is one link alone: MuJoCo's principal axes of a full tensor
/// (mju_eig3, an iteration with a loose stop) turn it, where a URDF reader takes the six numbers as
/// written (tests/crosscheck/urdf/seven_joint_arm.urdf's accelerations moved by 1.2e-7).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "import/robot.hpp"

namespace eomgen {

/// Whether MuJoCo's message is its refusal of an inertia with A + B < C.
bool refuses_unbalanced_inertia(const std::string& mujoco_error);

/// The URDF's text with its compiler's balanceinertia on (unchanged when it sets it itself).
std::string with_balanced_inertias(const std::string& urdf);

/// A link's inertia about its centre of mass as its <inertial> states it, in the link's frame:
/// principal moments and the quaternion of their axes (MuJoCo's body_inertia and body_iquat).
struct LinkInertia {
  std::string link;
  double mass = 0;
  Triple center{0, 0, 0};           // in the link's frame
  std::array<double, 9> tensor{};   // about the centre, in the link's frame, row-major
  Triple principal{0, 0, 0};
  Quaternion axes{1, 0, 0, 0};
  bool unbalanced = false;  // A + B < C for some order of the moments, or a moment below zero
  std::vector<std::string> fused;  // the links fixed to it whose mass it includes (urdf_fused_inertias)
};

/// Whether MuJoCo's message is its refusal to fuse fixed links whose inertia is not positive
/// definite (a moment below zero, or point masses in a line): MuJoCo fuses a floating base's fixed
/// links before balanceinertia could help.
bool refuses_to_fuse_singular_inertias(const std::string& mujoco_error);

/// The URDF's text with each link whose stated inertia has a principal moment at or below zero
/// stated instead as the mean magnitude of its moments about every axis (for a point mass, its
/// mass spread over a millimetre), on the same lines, so that MuJoCo's fusing takes it;
/// with_stated_inertias() then gives each body the file's inertia back.
std::string with_positive_moments(const std::string& urdf);

/// Every link of the URDF text with an <inertial> and an <inertia>, in the file's order.
std::vector<LinkInertia> urdf_link_inertias(const std::string& urdf);

/// Each link that other links with mass hang from by fixed joints (down the tree), with those links,
/// as one rigid body in its frame, as MuJoCo fuses them (a floating base's fixed links): the masses
/// summed, the centre of mass, and the tensor about it, Σ R I Rᵀ + m (|d|² 1 − d dᵀ) (Steiner).
std::vector<LinkInertia> urdf_fused_inertias(const std::string& urdf, const std::vector<LinkInertia>& links);

/// The links of the URDF text whose inertia no rigid body has: given back as stated, and left with
/// MuJoCo's balanced moments (fused into another body).
struct StatedInertias {
  std::vector<std::string> given_back, left_balanced;
};

/// Each body that is one link of the URDF text alone (its mass is the link's), or a link with those
/// fixed to it (its mass and centre theirs), takes the inertia the text states: its centre,
/// principal moments and axes to the last digit.
StatedInertias with_stated_inertias(std::vector<RobotBody>& bodies, const std::string& urdf);

}  // namespace eomgen
