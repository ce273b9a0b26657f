/// @file The inverse dynamics τ = M q'' − f of a tree of particles and its derivatives, in the
/// quantities of the articulated-body recursion: what the generated mass_matrix, forcing,
/// Jacobian and linearization need, one short term per entry where the symbolic M, f and ∂τ/∂x
/// of a chain have O(n) terms each.
///
/// Particle i hangs from its parent by d_i(q_J), which only its joint's coordinates J move, so
/// every particle k below i has ∂r_k/∂q_j = S_j (j ∈ J), and by Newton for each particle
///   τ_j = S_j · F_i − Q_j,   F_i = Σ_{k ∈ subtree(i)} m_k (a_k − g),
/// with Q the generalized forces besides gravity and inertia. The accelerations a_k change with
/// the coordinate l of joint i' only through d_i'' and only below i', so with m̄ the mass of the
/// deeper subtree when i and i' lie on one branch (0 when they do not):
///   M_jl = m̄ S_j · S_l,
///   ∂τ_j/∂q_l = m̄ S_j · ∂d_i''/∂q_l + [i' = i] ∂S_j/∂q_l · F_i − ∂Q_j/∂q_l,
///   ∂τ_j/∂q'_l = m̄ S_j · ∂d_i''/∂q'_l − ∂Q_j/∂q'_l.
#pragma once

#include <vector>

#include "derive/articulated_bodies.hpp"
#include "derive/equations.hpp"

namespace eomgen {

/// The tree's inverse dynamics; its quantities (composite masses, the subtrees' accelerations and
/// forces, the derivatives of the relative accelerations) are appended to `intermediates`.
TreeInverseDynamics articulated_inverse_dynamics(const Model& model, const Mechanics& mechanics, const ParticleTree& tree,
                                                 const ArticulatedAccelerations& forward,
                                                 const std::vector<GiNaC::symbol>& accelerations,
                                                 std::vector<Intermediate>& intermediates);

}  // namespace eomgen
