/// @file q'' of a tree of hinges and slides by Featherstone's articulated-body algorithm, in each
/// link's own joint frame and in the 3-vector form of spatial/joint_tree_dynamics.hpp: O(n)
/// operations where forming M and factoring it takes O(n·depth + Σ depth²), so that long chains
/// solve faster than by M = L D Lᵀ.
///
/// A link's angular acceleration α and its origin's acceleration a are, from its parent's,
///   (α, a) = X (α_p, a_p) + c + S q̈,   X (α_p, a_p) = (Eᵀ α_p, Eᵀ (a_p + α_p × r)),
///   c = (ω̄ × e q̇, Eᵀ (ω_p × (ω_p × r)) + 2 ω̄ × u q̇ + q̇² e × u),  S = (e, u),  ω̄ = Eᵀ ω_p,
/// with the base accelerating at −g. The force (N about the origin, F) that the link's subtree
/// needs is I (α, a) + p once the joints below satisfy their equations, with the 6×6 articulated
/// inertia I as three 3×3 blocks, (N, F) = (A α + B a, Bᵀ α + C a); a rigid body adds A = J_O,
/// B = [h]×, C = m 1 and p = (ω × J_O ω, ω × (ω × h)) (h = m c its first moment). Leaves first:
///   U = I S,  D = Sᵀ U,  w = Q − Sᵀ p,
///   I^a = I − U Uᵀ / D,  p^a = p + I c + U (w − Uᵀ c) / D,
/// carried to the parent as forces are, Xᵀ: N_p = E N + r × E F, F_p = E F, and with R = [r]×
///   A_p = E A Eᵀ − (E B Eᵀ) R − ((E B Eᵀ) R)ᵀ − R (E C Eᵀ) R,  B_p = E B Eᵀ + R E C Eᵀ,  C_p = E C Eᵀ.
/// Root first: q̈ = (w − Uᵀ (X (α_p, a_p) + c)) / D, then (α, a). Q is the generalized force on
/// the joint's velocity besides the bodies' inertia and gravity (applied forces, [energy], dissipation).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"
#include "spatial/joint_tree_derivatives.hpp"

namespace eomgen {

/// A direction of a joint's motion that moves no inertia: the articulated inertia the joint meets
/// is zero along it, so that M is singular and q'' undetermined (a free base whose link has no mass
/// and whose joint below turns about an axis through its origin, say). what(): which, in words.
struct SingularJointDirection : std::domain_error {
  using std::domain_error::domain_error;
};

/// q'' by the algorithm above, in the model's symbols and `intermediates`.
struct JointTreeAccelerations {
  std::vector<Intermediate> intermediates;
  std::vector<GiNaC::ex> accelerations;  // one per velocity
  bool asked = false;  // by `--forward-dynamics articulated`; else the header's writer weighs it against M
};

/// Whether the model's method is one the algorithm above solves: Lagrange II, or Appell's equations
/// for a tree with ball or free joints.
bool articulated_method(const Model& model);

/// Why the model's tree is not one the algorithm above solves (for `--forward-dynamics
/// articulated`), or nothing when it is: a joint tree (spatial/joint_tree_dynamics.hpp) each of
/// whose coordinates moves one joint, under Lagrange II (Appell's equations with ball and free
/// joints), whose [energy] kinetic (if any) couples no two rates. A joint of k velocities (a
/// ball's 3, a free joint's 6) has k columns S, and D = Sᵀ U is k × k, factored as L Δ Lᵀ.
std::optional<std::string> why_not_articulated_joint_tree(const Model& model);

/// Whether the algorithm above may be faster than M = L D Lᵀ for the tree `links`: when its
/// velocities are articulated_mean_depth deep on average or more (a joint's k columns one below
/// the other)
/// (tests/benchmarks/forward_dynamics_forms.py measures both forms in one process;
/// joint_tree_forward_dynamics.cpp has the figures). The header's writer then counts the
/// operations of both (emit/cpp_joint_tree.hpp).
bool articulated_body_may_pay(const std::vector<TreeLink>& links);

/// q'' for the tree `links` (parents first, their columns' velocities indices into
/// `generalized_forces`, Q above, free of q''), under `gravity`, with `joint_inertias`
/// a_j whose a_j q''_j the joints' equations add (a rotor's armature, by [energy] kinetic ½ Σ a_j q'_j²):
/// D + a_j in place of D.
JointTreeAccelerations joint_tree_accelerations(const std::vector<TreeLink>& links, const Vector3& gravity,
                                                const std::vector<GiNaC::ex>& generalized_forces,
                                                const std::vector<GiNaC::ex>& joint_inertias);

}  // namespace eomgen
