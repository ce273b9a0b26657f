/// @file What kinematics gives the derivation methods: each body's velocity
/// Jacobians and bias accelerations, the energies and the generalized forces.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"
#include "spatial/joint_tree_derivatives.hpp"
#include "spatial/joint_velocities.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

/// One particle or rigid body. With v = J q̇ + ∂r/∂t the velocity of its centre of
/// mass, its acceleration is a = J q̈ + bias_acceleration; likewise for the body-frame
/// angular velocity ω = J_ω q̇ + ω_t and angular acceleration α = J_ω q̈ + bias_angular_acceleration.
struct BodyKinematics {
  std::string name;
  GiNaC::ex mass;
  Vector3 position;                 // r of the centre of mass, inertial
  GiNaC::matrix velocity_jacobian;  // J: 3 × n, inertial components
  Vector3 velocity;                 // v, inertial
  Vector3 bias_acceleration;        // a − J q̈, inertial
  bool rotates = false;
  GiNaC::matrix angular_velocity_jacobian;  // J_ω: 3 × n, body frame
  Vector3 angular_velocity;                 // ω, body frame
  Vector3 bias_angular_acceleration;        // α − J_ω q̈, body frame
  GiNaC::matrix inertia{3, 3};              // body frame, about the centre of mass
};

/// A [[constraints]] entry with recursive kinematics: C (one entry per coordinate), b and γ of
/// C q̈ + γ = 0 through the frames' rotations and origins (RecursiveKinematics::rate_along_motion).
struct ConstraintTerms {
  std::vector<GiNaC::ex> jacobian;
  GiNaC::ex bias, acceleration_bias;
};

struct Mechanics {
  MotionSymbols motion;              // q, q̇, t, u
  std::vector<BodyKinematics> bodies;
  // T = ½ q'ᵀ M q' + b·q' + T0 + [energy] kinetic, with M the bodies' mass matrix: b and T0
  // come from explicit time dependence (∂r/∂t, ω at rest) and vanish for scleronomic bodies
  std::vector<GiNaC::ex> kinetic_linear;  // b, one per coordinate
  GiNaC::ex kinetic_at_rest;              // T0
  GiNaC::ex extra_kinetic_energy;         // [energy] kinetic alone
  GiNaC::ex potential_energy;        // V: gravity plus [energy] potential
  GiNaC::ex dissipation;             // R, Rayleigh's function
  std::vector<GiNaC::ex> generalized_force;  // Q of the applied forces and torques (without gravity and R)
  // no body position, rotation, energy or gravity depends on t, and nothing moves at rest (the
  // [energy] kinetic is a quadratic form in the velocities)
  bool scleronomic = true;
  std::vector<GiNaC::ex> potential_gradient;  // ∂V/∂q_j (through the frames, with recursive kinematics)
  /// Recursive kinematics: the frames' and bodies' quantities, in order (the model's first);
  /// every other expression here may contain their symbols, which `motion` then counts as moving.
  std::vector<Intermediate> intermediates;
  /// Recursive kinematics: the inverse dynamics τ(q, q', q'', u, t) = M q'' − f of the whole model
  /// in the symbols `acceleration_symbols` for q'', with its quantities (recursive_kinematics.hpp).
  std::vector<GiNaC::symbol> acceleration_symbols;
  std::vector<Intermediate> acceleration_intermediates;
  std::vector<GiNaC::ex> inverse_dynamics;
  /// A joint tree: inverse_dynamics is the bodies' τ plus the applied part, and the bodies'
  /// ∂τ/∂q and ∂τ/∂s are in closed form, in acceleration_intermediates.
  std::optional<BodiesGradient> bodies_gradient;
  /// Recursive kinematics: the bodies' M by the composite-body recursion, when it applies.
  std::optional<GiNaC::matrix> composite_mass_matrix;
  /// A tree of frames joined by joints (spatial/joint_tree_dynamics.hpp): the bodies' part of f,
  /// −τ(q, q̇, q̈ = 0) with gravity, from the Newton–Euler recursion in the frames' coordinates;
  /// potential_gradient is then that of [energy] potential alone.
  std::optional<std::vector<GiNaC::ex>> tree_bias_forces;
  std::vector<int> coordinate_parents;  // of the joint tree (Equations::coordinate_parents)
  std::optional<GiNaC::ex> tree_kinetic_energy;  // the bodies' T by the tree's velocity recursion
  /// A joint tree with ball or free joints: its pseudo-velocities, in which M, the bias forces,
  /// τ and T above are written (spatial/joint_velocities.hpp); the rest stays in q and q'.
  std::optional<JointVelocities> tree_velocities;
  /// A joint tree's links in their joint frames (spatial/joint_tree_derivatives.hpp), for the
  /// articulated-body algorithm (spatial/joint_tree_forward_dynamics.hpp); empty otherwise.
  std::vector<TreeLink> tree_links;
  /// Recursive kinematics: each constraint's terms through the frames, in file order.
  std::vector<ConstraintTerms> constraint_terms;
};

/// Hiller §2.1, §3.1, §3.9: velocities by the chain rule through q and t,
/// ω from skew(ω_B) = Rᵀ·dR/dt, energies, and Q_j = Σ F·∂v/∂q̇_j + M·∂ω/∂q̇_j.
Mechanics compute_mechanics(const Model& model);

/// T(q, q', t) = Σ ½ m v·v + ½ ωᵀ I ω of the bodies plus [energy] kinetic, tidied.
GiNaC::ex kinetic_energy_of(const Mechanics& mechanics);

/// T + V is a first integral at zero inputs (Hiller §3.6): no applied forces then, no
/// dissipation, nothing depends on time explicitly, and T is a quadratic form in the velocities.
bool conserves_energy_without_inputs(const Mechanics& mechanics, const Symbols& symbols);

/// Whether T is a quadratic form in `velocities` (T1 = T0 = 0): by Euler's theorem on homogeneous
/// functions, exactly when Σ v ∂T/∂v = 2 T, decided by tidying the difference along `motion`.
bool quadratic_form_in(const GiNaC::ex& T, const std::vector<GiNaC::realsymbol>& velocities, const MotionSymbols& motion);

/// The symbols that change along a motion: q, q', t and u.
MotionSymbols motion_symbols(const Symbols& symbols);

/// dx/dt along the motion, without the q̈ terms: Σ ∂x/∂q_k q̇_k + ∂x/∂t
/// (for x linear in q̇ this is the bias term of its time derivative).
GiNaC::ex time_derivative(const GiNaC::ex& x, const Symbols& symbols);

/// Body-frame angular velocity of R = R1·…·Rk: Σ_i (R_{i+1}⋯R_k)ᵀ e_i · d(angle_i)/dt.
Vector3 angular_velocity_of_sequence(const std::vector<ElementaryRotation>& sequence, const Symbols& symbols);

/// Body-frame angular velocity from skew(ω) = Rᵀ·dR/dt, for a rotation given as a matrix.
Vector3 angular_velocity_of_matrix(const GiNaC::matrix& R, const Symbols& symbols, const MotionSymbols& motion);

}  // namespace eomgen
