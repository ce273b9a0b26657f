/// @file MuJoCo 3.3.6 replaced <flag passive="disable"/> by two flags of its own, spring and damper,
/// which MuJoCo 2.2.2's schema refuses. The file is read with them written as 2.2.2 reads them, and
/// what they switch off is kept for the import to take off (option_forces.hpp).
#pragma once

#include <string>

namespace eomgen {

/// What a file's <flag spring="disable" damper="disable"/> switches off. With both off, MuJoCo
/// 3.3.6 skips every passive force, the medium's included, as 2.2's passive="disable" did; with one
/// off, the medium still acts.
struct PassiveSwitches {
  bool springs_off = false;  // the joints' and fixed tendons' springs (stiffness)
  bool dampers_off = false;  // their dampers (damping)
  bool all_off() const { return springs_off && dampers_off; }
};

/// Whether MuJoCo's error is its schema refusing the spring or damper flag of an <option>'s <flag>.
bool refuses_passive_flag(const std::string& mujoco_error);

/// The switches the <flag> elements of `mjcf` state, with `mjcf` rewritten for MuJoCo 2.2.2: the two
/// attributes taken out, and passive="disable" put in their place where the text switches both off.
/// Every other byte and line break stays where it was.
PassiveSwitches translate_passive_flags(std::string& mjcf);

}  // namespace eomgen
