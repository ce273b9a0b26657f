/// @file Recursive kinematics (Hiller §3.9, the recursion of multibody codes): each frame's
/// partial angular velocities, partial velocities and bias accelerations from its parent's,
/// as intermediates, so that a chain of n frames costs O(n²) quantities of a few products each
/// instead of expressions multiplied out in q with up to 4ⁿ terms.
///
/// With a child C placed in its parent P by R_rel(q) and o_rel(q) (parent coordinates), body
/// components for angular quantities and inertial ones for translation:
///   W_C,j = R_relᵀ W_P,j + ∂ω_rel/∂q̇_j           ω_C = R_relᵀ ω_P + ω_rel
///   α_C   = R_relᵀ α_P − ω_rel × R_relᵀ ω_P + α_rel
///   V_C,j = V_P,j + R_P (W_P,j × o_rel + ∂o_rel/∂q_j)
///   a_C   = a_P + R_P (α_P × o_rel + ω_P × (ω_P × o_rel) + 2 ω_P × ȯ_rel + ö_rel)
/// where α and a are the bias parts (those of q̈ = 0), and ∂R_C/∂q_j = R_C [W_C,j]×.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "kinematics/mechanics.hpp"

namespace eomgen {

/// The motion of a frame or body: its rotation and origin (symbols or constants) and the
/// quantities of the recursion above.
struct FrameMotion {
  GiNaC::matrix rotation{3, 3};  // body components to inertial
  Vector3 origin{0, 0, 0};       // inertial
  GiNaC::matrix partial_angular_velocity;  // W: 3 × n, body components
  Vector3 angular_velocity{0, 0, 0};       // ω, body components
  Vector3 angular_bias{0, 0, 0};           // α − W q̈, body components
  GiNaC::matrix partial_velocity;          // V: 3 × n, inertial, of the origin
  Vector3 acceleration_bias{0, 0, 0};      // a − V q̈, inertial
};

class RecursiveKinematics {
 public:
  /// A frame's rotation entry or origin component: its rate and its acceleration at q̈ = 0.
  struct PoseRates {
    GiNaC::ex rate, bias_acceleration;
  };

  /// The motions of the model's frame links, appending their intermediates to `intermediates`.
  RecursiveKinematics(const Model& model, std::vector<Intermediate>& intermediates);

  /// A body placed in a frame: J, v, a_bias (and ω, J_ω, α_bias for a rigid body).
  BodyKinematics body(const std::string& name, const GiNaC::ex& mass, const Vector3& position,
                      const FramePlacement& placement, bool rigid);

  /// ∂x/∂q_j for every j by the chain rule through the frames' rotations and origins.
  std::vector<GiNaC::ex> gradient(const GiNaC::ex& x) const;

  /// dx/dt along the motion without the q̈ terms, for x in q, q̇, t and the frames' rotations and
  /// origins: Σ ∂x/∂s ṡ + Σ ∂x/∂q_j q̇_j + ∂x/∂t, with Ṙ = R[ω]×, ȯ = V q̇; taken twice
  /// (`twice`), the second time with R̈ = R([α]× + [ω]×[ω]×) and ö = a of q̈ = 0, the frames'
  /// bias accelerations: a holonomic constraint's γ (Hiller §2.2).
  GiNaC::ex rate_along_motion(const GiNaC::ex& x, bool twice) const;

  /// The inertia and gravity part of the inverse dynamics, τ_j = Σ over the bodies of
  /// V_j·m(a − g) + W_j·(I α + ω × I ω) at the accelerations `q''` (symbols), by the
  /// Newton–Euler recursion: accelerations forward, each subtree's force and moment (about the
  /// frame's origin) backward, projected on each frame's own partial twist (inverse_dynamics.cpp).
  /// Its quantities are appended to `out`. O(n) code, so its derivatives are O(n²).
  std::vector<GiNaC::ex> inverse_dynamics(const std::vector<GiNaC::symbol>& accelerations, const Vector3& gravity,
                                          std::vector<Intermediate>& out);

  /// M by the composite-body recursion (recursive_composite_inertia.cpp): each frame's subtree
  /// mass, first moment and inertia about its origin, backward, and M_jk = s_j·p_k + s_j^ω·L_k,
  /// the momentum and angular momentum of the subtree of q_j's frame moved by q̇_k. O(n²) code
  /// instead of the O(n³) of Σ m V_j·V_k over the bodies. Nothing when a coordinate turns or
  /// moves more than one frame, or a body moves in its frame or is outside the frames.
  std::optional<GiNaC::matrix> composite_mass_matrix(std::vector<Intermediate>& out) const;

  /// Three intermediates WHO.LABEL_x, _y, _z (constants and lone symbols stay as they are).
  static Vector3 named_vector(std::vector<Intermediate>& out, const std::string& who, const std::string& label,
                              const Vector3& x);

 private:
  FrameMotion child(const FrameMotion& parent, const GiNaC::matrix& relative,
                    const std::vector<ElementaryRotation>& sequence, const Vector3& relative_origin,
                    const std::string& name);
  GiNaC::ex named(const std::string& name, const std::string& label, const GiNaC::ex& definition);

  struct Acceleration {
    Vector3 angular{0, 0, 0};  // α, body components
    Vector3 linear{0, 0, 0};   // a of the origin, inertial
  };
  Acceleration child_acceleration(const FrameMotion& parent, const Acceleration& p, const GiNaC::matrix& relative,
                                  const std::vector<ElementaryRotation>& sequence, const Vector3& relative_origin,
                                  const std::vector<GiNaC::symbol>& accelerations) const;
  Vector3 relative_angular_velocity(const GiNaC::matrix& relative, const std::vector<ElementaryRotation>& sequence) const;

  const Model& model_;
  const Symbols& symbols_;
  MotionSymbols motion_;
  std::vector<Intermediate>& intermediates_;
  FrameMotion inertial_;
  std::vector<FrameMotion> frames_;
  // a frame's rotation entry or origin component → its partial derivatives by q_j
  std::map<GiNaC::ex, std::vector<GiNaC::ex>, GiNaC::ex_is_less> partials_;
  // the same → its rate and its bias acceleration (that of q̈ = 0)
  std::map<GiNaC::ex, PoseRates, GiNaC::ex_is_less> pose_rates_;
};

}  // namespace eomgen
