/// @file The derived equations of motion M(q,t)·q̈ = f(q,q̇,u,t), with what
/// the output formats need to name things; the plain result of every method.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"
#include "spatial/joint_tree_derivatives.hpp"
#include "spatial/joint_tree_forward_dynamics.hpp"

namespace eomgen {

/// The constraints at velocity level, C(q,t)·q' + b(q,t) = 0 (Hiller §2.2); the holonomic
/// ones g(q,t) = 0 differentiated once, so C = ∂g/∂q and b = ∂g/∂t for them. At acceleration
/// level C q'' + acceleration_bias = 0.
struct ConstraintSet {
  std::vector<std::string> names;
  std::vector<bool> holonomic;
  std::vector<GiNaC::ex> position;           // g(q,t); 0 for nonholonomic rows
  GiNaC::matrix jacobian;                    // C: m × n (coordinates)
  std::vector<GiNaC::ex> bias;               // b(q,t)
  std::vector<GiNaC::ex> acceleration_bias;  // d/dt(C q' + b) − C q'', in q, q', t
  std::size_t size() const { return names.size(); }
  std::size_t num_holonomic() const;
};

/// The inverse dynamics τ = M q'' − f of a tree of particles in the quantities of the
/// articulated-body recursion (derive/articulated_inverse_dynamics.hpp), for the generated code:
///   M_jl = m̄ S_j · S_l,   ∂τ_j/∂q_l = m̄ S_j · ∂d''/∂q_l + rest,   ∂τ_j/∂q'_l = m̄ S_j · ∂d''/∂q'_l + rest,
/// with m̄ the mass of the subtree that couples the coordinates j and l (none on different branches).
struct TreeInverseDynamics {
  std::vector<Vector3> axes;                      // S_j = ∂r/∂q_j of the particle q_j moves
  std::vector<Vector3> acceleration_by_coordinate;  // ∂d''/∂q_l of that particle's relative acceleration
  std::vector<Vector3> acceleration_by_velocity;    // ∂d''/∂q'_l
  std::vector<GiNaC::ex> subtree_masses;          // m̄ of each particle's subtree
  std::vector<int> coupling;                      // n × n: the particle whose m̄ couples j and l, or −1
  /// The coordinates as a tree of their own, one coordinate per joint axis: a joint's first coordinate
  /// hangs from the last coordinate of the particle's nearest parent that has any (−1: the ground),
  /// each further one from the one before it. `coordinate_order` lists them parents first; the last
  /// coordinate of a joint carries the particle's mass and those of particles rigidly attached below
  /// it (`carried_masses`, zero for the other coordinates).
  std::vector<std::size_t> coordinate_order;
  std::vector<int> coordinate_parent;
  std::vector<GiNaC::ex> carried_masses;
  std::vector<std::size_t> joint_carrier;  // for each coordinate, the last coordinate of its joint
  std::vector<GiNaC::ex> forcing;                 // f = −τ at q'' = 0
  /// the rest of ∂τ/∂(q, q', u), n × (2n + inputs) row by row: the derivatives of S and of the
  /// other generalized forces, and the input columns; mostly zero
  std::vector<GiNaC::ex> gradient_rest;
  /// q'' = M⁻¹ b by the recursion for generalized forces b given as symbols (the Jacobian's solves)
  std::vector<GiNaC::symbol> forces;
  std::vector<GiNaC::ex> accelerations_of_forces;
};

/// The form of a tree of particles (DynamicsForm::particle_tree): forward dynamics by the
/// articulated-body recursion (derive/articulated_bodies.hpp), q'' in the recursion's quantities,
/// for the generated rhs, and the same tree's M, f and ∂τ/∂(q, q', u) (q'' held as
/// `acceleration_symbols`) in them, equal to Equations::mass_matrix and forcing. Not printed.
struct ArticulatedForwardDynamics {
  std::vector<GiNaC::symbol> acceleration_symbols;
  std::vector<Intermediate> intermediates;
  std::vector<GiNaC::ex> accelerations;
  TreeInverseDynamics inverse_dynamics;
};

/// The form of recursive kinematics and trees of joints (DynamicsForm::newton_euler): the inverse
/// dynamics τ(q, q', q'', u, t) = M q'' − f by the Newton–Euler recursion, in the symbols
/// `acceleration_symbols` for q'', whose quantities come after Equations::intermediates: the
/// generated Jacobian and linearization differentiate it with q'' held, O(n²) code where ∂M/∂x and
/// ∂f/∂x entry by entry are O(n³). Not part of the printed equations.
struct NewtonEulerRecursion {
  std::vector<GiNaC::symbol> acceleration_symbols;
  std::vector<Intermediate> acceleration_intermediates;
  std::vector<GiNaC::ex> inverse_dynamics;
  /// A joint tree: inverse_dynamics is the bodies' τ plus the applied part, and the bodies' ∂τ/∂q
  /// (velocities × coordinates) and ∂τ/∂s (velocities × velocities) are in closed form, in
  /// acceleration_intermediates, or the header's loops over a long tree's links: the header's
  /// tangent sweep then runs through the applied part alone. Empty otherwise.
  std::optional<BodiesGradient> bodies_gradient;
  /// the links of those loops (emit/cpp_tree_gradient_loops.hpp), or null
  const TreeLinkTables* gradient_loops() const {
    return bodies_gradient ? bodies_gradient->loops() : nullptr;
  }
  /// A joint tree's q'' by the articulated-body algorithm, where ModelChoice::forward_dynamics asks
  /// for it or the tree is deep enough: the header's rhs takes it where asked or where its code is
  /// shorter than M's (emit/cpp_joint_tree.hpp); everything else uses M and the tree's τ.
  std::optional<JointTreeAccelerations> joint_tree_accelerations;
};

/// The form of Hamilton's equations of a larger model, where M⁻¹ would swell
/// (DynamicsForm::momentum): der(q) solves mass_matrix·der(q) = p − bias in the generated code, and
/// H, f, T and the outputs are written in q and der(q) (coordinate_rates are then der(q) itself).
struct MomentumSolve {
  GiNaC::matrix mass_matrix;
  std::vector<GiNaC::ex> bias;
};

/// A quantity that stays constant along every motion at zero inputs (Hiller §3.6, §3.8.3).
struct FirstIntegral {
  std::string name;        // "energy" (T + V), "jacobi_integral", or p_<coordinate>
  GiNaC::ex expression;    // in the state's variables
  std::string reason;      // why it is conserved, in words
  /// A momentum that is row `mass_matrix_row` of M times the velocities (T = ½ vᵀ M v and the
  /// coordinate's rate a velocity of its own, checked at two states): the header writes it from
  /// mass_matrix, where its chain rule through a tree's quantities can run to megabytes. −1: not so.
  int mass_matrix_row = -1;
};

/// The derived equations of motion M·v' = f with q' = v, or, for Appell's equations,
/// q' = coordinate_rates(q, s, t) with the pseudo-velocities s as v (then M and f are
/// in s, and `symbols.velocities` are the pseudo-velocities). Lagrange I adds the
/// constraint forces: M q'' = f + Cᵀλ.
struct Equations {
  std::string model_name, title, method;
  std::string source;  // the model file's path as given
  Symbols symbols;
  std::size_t degrees_of_freedom = 0;
  /// Recursive kinematics: quantities of the frames and bodies, each defined in the model's
  /// symbols and earlier ones, that the expressions below may contain (empty otherwise).
  std::vector<Intermediate> intermediates;
  /// How the header forms q'' and its derivatives, one form per model, chosen where the equations
  /// are derived (emit/dynamics_form.hpp reads it): M q'' = f as written (std::monostate), or one of
  /// the forms above with what it needs. Lagrange I's multipliers come on top of any.
  std::variant<std::monostate, MomentumSolve, NewtonEulerRecursion, ArticulatedForwardDynamics> dynamics;
  const NewtonEulerRecursion* newton_euler() const { return std::get_if<NewtonEulerRecursion>(&dynamics); }
  NewtonEulerRecursion* newton_euler() { return std::get_if<NewtonEulerRecursion>(&dynamics); }
  const ArticulatedForwardDynamics* articulated() const { return std::get_if<ArticulatedForwardDynamics>(&dynamics); }
  const MomentumSolve* momentum() const { return std::get_if<MomentumSolve>(&dynamics); }
  MomentumSolve* momentum() { return std::get_if<MomentumSolve>(&dynamics); }
  /// a joint tree's q'' by the articulated-body algorithm, or null
  const JointTreeAccelerations* joint_tree_accelerations() const {
    return newton_euler() && newton_euler()->joint_tree_accelerations ? &*newton_euler()->joint_tree_accelerations : nullptr;
  }
  /// the links of a long joint tree's gradient loops, or null (NewtonEulerRecursion::gradient_loops)
  const TreeLinkTables* gradient_loops() const { return newton_euler() ? newton_euler()->gradient_loops() : nullptr; }
  /// the symbols of q'' in which the form's inverse dynamics is written (empty for M q'' = f)
  const std::vector<GiNaC::symbol>& acceleration_symbols() const;
  /// For equations whose M or f a transformation has changed: the rhs then solves M q'' = f (a
  /// recursion's τ stays for the derivatives, which it still gives)
  void solve_by_mass_matrix();
  /// A tree of joints (spatial/joint_tree_dynamics.hpp): for each coordinate, the one above it
  /// (−1 at a root): for a tree numbered parents first, the coordinate of the nearest joint above
  /// its own; with joints that follow another's coordinate, or another numbering, the one that the
  /// factorization's fill-in puts there. M_ij is zero unless one of i, j is above the other, and
  /// the header factors M from the leaves (emit/cpp_ldlt.hpp). Empty otherwise.
  std::vector<int> coordinate_parents;
  /// Ball and free joints: the coordinates w, x, y, z of each unit quaternion, whose length the
  /// motion keeps (a zero eigenvalue of every linearization, not a property of the system).
  std::vector<std::array<std::size_t, 4>> quaternions;
  GiNaC::matrix mass_matrix;           // n × n, symmetric
  std::vector<GiNaC::ex> forcing;      // n
  GiNaC::ex kinetic_energy, potential_energy, dissipation;
  /// T = ½ vᵀ M v (derive/quadratic_kinetic_energy.hpp): the header's kinetic_energy then takes
  /// M from mass_matrix instead of writing the recursion's T out again. Set by the pipeline.
  bool kinetic_energy_from_mass_matrix = false;
  std::vector<NamedSymbolic> outputs;
  ConstraintSet constraints;
  bool has_multipliers = false;  // Lagrange I: M q'' = f + Cᵀλ, solved together with C q'' + γ = 0
  /// Appell (Hiller §4.3): q' = W(q,t)·s + w(q,t); empty when q' = v.
  std::vector<GiNaC::ex> coordinate_rates;
  std::vector<GiNaC::realsymbol> coordinate_velocities;      // the model's der(q), when v are pseudo-velocities
  std::vector<NamedSymbolic> pseudo_velocity_definitions;    // s = Y q' + y, as given or chosen
  GiNaC::ex acceleration_energy;                             // S(q, s, s', t), without terms free of s'
  /// A tree with ball or free joints takes M and f from its recursions and forms no S.
  bool acceleration_energy_formed() const { return !(acceleration_energy.is_zero() && newton_euler()); }
  GiNaC::ex hamiltonian;  // Hamilton: H(q, p, t); the velocities are then the momenta p, M = I and f = p'
  /// Hamilton's equations in the momentum form (MomentumSolve)
  bool solves_for_velocities() const { return momentum() != nullptr; }
  std::vector<GiNaC::realsymbol> pseudo_accelerations;       // s', as they appear in S
  std::size_t num_velocities() const { return symbols.velocities.size(); }
  bool uses_pseudo_velocities() const { return !coordinate_rates.empty(); }
  /// T + V is a first integral when the inputs are zero: no dissipation, no applied
  /// forces at u = 0, and no explicit time dependence (Hiller §3.6).
  bool conserves_energy_without_inputs = false;
  std::vector<FirstIntegral> first_integrals;  // filled by the pipeline for every method
  /// Where each particle's and body's centre of mass is, r(q, t), for pictures of the motion
  struct BodyPosition {
    std::string name;
    Vector3 position;
  };
  std::vector<BodyPosition> body_positions;  // filled by the pipeline
  /// What `eomgen animate` draws (Model::drawing), with a tree of particles' rods from each
  /// particle to the one it hangs from; filled by the pipeline, empty for linearized equations.
  std::vector<DrawnBody> drawing;
  Vector3 gravity{0, 0, 0};  // the model's [gravity], for the drawing
  std::vector<Scene> scenes;                 // the model file's [scenes], for simulate --scene and eomgen scene
  std::vector<Variant> variants_declared;    // its [variants], the candidates of eomgen scene
  /// Routh's reduction: R(q, q', t; p) and each eliminated coordinate with its rate der(q_c)(q, q', p)
  GiNaC::ex routhian;
  std::vector<NamedSymbolic> eliminated_coordinates;
  /// Linearization M q'' + P q' + Q q = B u about states with q'' = 0 (Hiller §5.3),
  /// in the coordinates and velocities of the state: filled by add_linearization().
  bool has_linearization = false;
  GiNaC::matrix linear_damping_gyroscopic, linear_stiffness_circulatory, linear_input;  // P, Q, B
};

/// The model symbols an expression depends on, through the intermediates of recursive
/// kinematics too (each intermediate's are gathered once, in order).
class SymbolDependence {
 public:
  explicit SymbolDependence(const std::vector<Intermediate>& intermediates);
  /// Adds the model symbols of x to `out`.
  void add(const GiNaC::ex& x, GiNaC::exset& out) const;

 private:
  std::map<GiNaC::ex, GiNaC::exset, GiNaC::ex_is_less> of_;
};

/// P = −∂f/∂q', Q = −∂f/∂q, B = ∂f/∂u, each entry kept compact.
void add_linearization(Equations& equations);

/// Hamilton's equations with H = T(p) + V(q): q' depends on the momenta alone and p' on
/// the coordinates and time alone, so Störmer–Verlet in canonical variables is explicit.
bool separable_hamiltonian(const Equations& equations);

/// Coordinates on which neither the mass matrix nor the forcing depends (Hiller §3.8).
std::vector<bool> cyclic_coordinates(const Equations& equations);

}  // namespace eomgen
