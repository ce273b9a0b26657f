/// @file The derivation methods; each is one file with the same signature.
#pragma once

#include <optional>
#include <string>

#include "derive/equations.hpp"
#include "kinematics/mechanics.hpp"

namespace eomgen {

using DerivationMethod = Equations (*)(const Model&, const Mechanics&);

/// Lagrange's equations of the second kind (Hiller §3.3).
Equations derive_lagrange2(const Model& model, const Mechanics& mechanics);

/// Lagrange's equations of the first kind, with multipliers (Hiller §2.4, §4.2).
Equations derive_lagrange1(const Model& model, const Mechanics& mechanics);

/// Appell's equations with pseudo-velocities (Hiller §4.3). Throws std::invalid_argument
/// with the reason when the pseudo-velocities do not determine the velocities.
Equations derive_appell(const Model& model, const Mechanics& mechanics);

/// Appell's equations of a tree of joints with ball or free joints (mechanics.tree_velocities set),
/// from the spatial recursions; derive_appell takes this way for such a model.
Equations derive_joint_tree_appell(const Model& model, const Mechanics& mechanics);

/// Hamilton's canonical equations in x = [q; p] (Hiller §3.8); holonomic models.
Equations derive_hamilton(const Model& model, const Mechanics& mechanics);

/// The Newton–Euler form (NewtonEulerRecursion) where recursive kinematics gave `mechanics` an
/// inverse dynamics; `e` keeps its form otherwise.
void take_newton_euler_recursion(const Mechanics& mechanics, Equations& e);

/// The method a model file names, if this version of eomgen has it.
std::optional<DerivationMethod> find_method(const std::string& name);

/// Why a model cannot be derived by its method yet (constraints, pseudo-velocities,
/// a method that is still to come), or empty when it can.
std::string method_refusal(const Model& model);

}  // namespace eomgen
