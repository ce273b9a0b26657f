/// @file ∂τ/∂q and ∂τ/∂q' of a joint tree's bodies in closed form (the analytic derivatives of the
/// recursive Newton–Euler algorithm of Carpentier and Mansard, RSS 2018, derived here in world
/// coordinates), for jacobian_state and linearization.
///
/// In world Plücker coordinates a joint j's motion subspace S_j turns with every joint above it, and
/// a change of q_j moves its whole subtree Φ_j rigidly, by the twist S_j. Whatever turns with Φ_j
/// has the derivative S_j × (·); the parent's velocity v_λ and acceleration a_λ (gravity included)
/// do not turn, and τ_k = S_k·F_k is invariant under turning all of them together. What is left,
/// with Ψ'_j = v_λ × S_j, Ψ''_j = a_λ × S_j + v_λ × Ψ'_j and, for each link, the composite inertia
/// I^C, force F and B^C = Σ B_l with B_l x = I_l (x × v_l) + x ×* (I_l v_l) + v_l ×* (I_l x):
///   ∂τ_k/∂q_j  = S_k·(I^C_k Ψ''_j + B^C_k Ψ'_j)         for k in Φ_j,
///              = S_k·(S_j ×* F_j + I^C_j Ψ''_j + B^C_j Ψ'_j)   for k above j;
///   ∂τ_k/∂q'_j = S_k·(2 I^C_k Ψ'_j + B^C_k S_j)          for k in Φ_j,
///              = S_k·(2 I^C_j Ψ'_j + B^C_j S_j)          for k above j.
/// Per link a fixed cost; per pair of a joint and one it carries, two dot products of six-vectors
/// (with I^C_k S_k and B^C_kᵀ S_k formed once per link), where the tangent sweep through the
/// recursion in joint frames transports tangents of forces and moments for each pair.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

/// A link of the tree in its parent's joint frame (spatial/joint_tree_dynamics.hpp): its turn E
/// (own components to the parent's), the offset r of its origin, its one joint's axis e and the
/// origin's velocity u per unit rate (none for a fixed link), and its bodies in its own coordinates.
struct TreeLink {
  std::string name;
  int parent = -1;
  GiNaC::matrix turn{3, 3};
  Vector3 offset{0, 0, 0};
  int velocity = -1;  // the velocity (and coordinate) of its joint, −1 for a fixed link
  GiNaC::ex rate = 0;
  Vector3 axis{0, 0, 0}, origin_velocity{0, 0, 0};
  struct Body {
    GiNaC::ex mass;
    Vector3 center;
    GiNaC::matrix inertia{3, 3};  // about the centre
  };
  std::vector<Body> bodies;
};

struct InverseDynamicsGradient {
  GiNaC::matrix coordinates;  // ∂τ_i/∂q_j, n×n
  GiNaC::matrix velocities;   // ∂τ_i/∂q'_j, n×n
};

/// The derivatives above, of τ at the accelerations `ddq`, for n coordinates each moving one link
/// (links parents first); their quantities are appended to `out` as intermediates.
InverseDynamicsGradient joint_tree_gradient(const std::vector<TreeLink>& links, const Vector3& gravity,
                                            const std::vector<GiNaC::ex>& ddq, std::size_t n,
                                            std::vector<Intermediate>& out);

}  // namespace eomgen
