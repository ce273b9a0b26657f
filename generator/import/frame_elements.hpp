/// @file MuJoCo 3's <frame> element (3.1): a pose, with no body of its own, that places the bodies,
/// geoms and sites inside it; MuJoCo 2.2.2's schema refuses it (Apptronik's Apollo has them). Such a
/// file is read with each frame written as a <body> welded to its parent, at the frame's pose (a
/// body takes the same pos, quat, euler, axisangle, xyaxes, zaxis and childclass), which moves as
/// one with its parent: the same kinematics. The mass stays as MuJoCo 3 counts it: where the enclosing
/// body states its <inertial>, the geoms inside the frame weigh nothing in MuJoCo 3, and the welded
/// body gets an <inertial> of zero mass; where the enclosing body takes its inertia from its geoms,
/// the welded body's geoms weigh what they weighed there, on the same rigid whole. A frame's name
/// is dropped (MuJoCo keeps frames' names apart from bodies'; nothing refers to one). Not where a
/// frame holds a joint or an <inertial>, which a welded body would move: MuJoCo's error stands.
#pragma once

#include <optional>
#include <string>

namespace eomgen {

/// Whether MuJoCo's error is its schema refusing a <frame> element.
bool refuses_frame_element(const std::string& mujoco_error);

/// The text with every <frame> written as a welded <body> (see above); nothing where one cannot be.
std::optional<std::string> with_frames_as_bodies(const std::string& mjcf);

/// How many <frame> elements the text has (outside comments).
int frame_elements(const std::string& mjcf);

}  // namespace eomgen
