/// @file Actuators and fixed tendons as the model file's forces: a motor or servo on a joint or on a
/// fixed tendon (its length Σ cᵢ qᵢ) as an input and the generalized forces it gives, and a fixed
/// tendon's spring and damper as energies.
#pragma once

#include <vector>

#include "import/model_sections.hpp"
#include "import/robot.hpp"

namespace eomgen {

/// The actuators as inputs and [[forces]] generalized, in their coordinates (a joint that follows
/// another's coordinate passes m times its force on to it).
void add_actuators(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols, Names& names, Sections& out);

/// The fixed tendons' springs and dampers into [energy].
void add_tendon_springs(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols, Sections& out);

}  // namespace eomgen
