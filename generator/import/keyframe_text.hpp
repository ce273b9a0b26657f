/// @file Keyframes whose arrays end in white space (a qpos written over several lines, its closing
/// quote on a line of its own, as MuJoCo Playground's OP3 has it): MuJoCo 2.2.2 counts the space as
/// one more number and refuses the key ("invalid qpos size"), where MuJoCo 3 reads it. Such a file is
/// read with the <key> values' trailing white space taken out; nothing else changes.
#pragma once

#include <string>

namespace eomgen {

/// Whether MuJoCo's error is its refusal of a keyframe array's length.
bool refuses_keyframe_length(const std::string& mujoco_error);

/// The text with the white space at the end of every <key> attribute's value taken out (its line
/// breaks kept, after the closing quote).
std::string with_keyframe_values_trimmed(const std::string& mjcf);

}  // namespace eomgen
