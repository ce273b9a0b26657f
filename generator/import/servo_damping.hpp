/// @file MuJoCo 3's kv and dampratio on a <position> actuator: its velocity gain, the servo's force
/// then kp (u − q) − kv q' (MuJoCo 2.2.2's position servo has kp alone, and its schema refuses both),
/// and that gain given as a damping ratio ζ instead, kv = 2 ζ sqrt(kp m), m the inertia that the
/// actuator sees at the model's initial pose (MuJoCo 3's mj_setConst: each velocity's diagonal entry
/// of the mass matrix at qpos0, armature included, over the square of its transmission). The file
/// is read with each kv written as the actuator's `user` value and each dampratio as its negative,
/// which MuJoCo 2.2.2 resolves through defaults and classes as MuJoCo 3 resolves the two (one
/// overrides the other there, as one user value overrides another here), and the import takes them
/// from actuator_user (mjcf_reader.cpp). A file with user values of its own keeps them: its kv and
/// dampratio are then left out with a warning (newer_mjcf.hpp).
#pragma once

#include <optional>
#include <string>

#include <mujoco/mujoco.h>

namespace eomgen {

/// Whether MuJoCo's error is its schema refusing kv or dampratio on a <position> actuator (or its default).
bool refuses_position_damping(const std::string& mujoco_error);

/// Whether an actuator of the text (or an actuator default) sets `user`: then kv cannot borrow it.
bool has_actuator_user_values(const std::string& mjcf);

/// The text with kv="..." of every <position> tag (outside comments) written as user="..." and
/// dampratio="..." as user="-...": nothing where a dampratio is negative (MuJoCo 3 refuses it).
std::optional<std::string> with_servo_damping_as_user(const std::string& mjcf);

/// Whether actuator `a` has a position servo's shape: an affine bias whose position coefficient is
/// minus its gain (bias₁ = −kp), whatever its element.
bool position_like(const mjModel* m, int a);

/// Whether actuator `a` is one whose positive velocity coefficient MuJoCo 3's mj_setConst reads as a
/// damping ratio: position-like (its gain is minus its position coefficient, whatever its element),
/// its bias affine, with biasprm[2] > 0, which MuJoCo 2.2.2 would take as a velocity feedback that
/// feeds motion. (MuJoCo 3 converts it whatever the bias type; without an affine bias it acts nowhere.)
bool reads_bias_as_damping_ratio(const mjModel* m, int a);

/// The velocity gain kv of position servo `a` whose user value says `damping` (servo_damping.hpp's
/// encoding: kv itself, or minus the damping ratio), `d` holding the model at qpos0 after
/// mj_fwdPosition (its mass matrix and the actuators' moments).
double servo_velocity_gain(const mjModel* m, const mjData* d, int a, double damping);

}  // namespace eomgen
