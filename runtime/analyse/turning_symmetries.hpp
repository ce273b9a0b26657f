/// @file Turns that the equations of motion do not see. A body on a ball joint hanging under gravity
/// may be turned about the vertical through its pivot, q -> r(θ, a) ⊗ q with its angular velocity in
/// its own axes kept, and every motion turns into a motion. Such a symmetry makes each turned
/// equilibrium an equilibrium too (a zero eigenvalue along the turn) and conserves the momentum about
/// the axis (a second zero, in a Jordan block with the first): the turn is cyclic in all but name,
/// and the verdict is taken with respect to the rest, as it is for a cyclic coordinate (Hiller
/// §7.1). Without the turn recognized, the hanging top was called unstable: its yaw drifts after a
/// push about the vertical.
///
/// The turn about a world axis a is the vector field ξ_a(x) = (½ (0, a) ⊗ q, 0) on the quaternion's
/// components. It is a symmetry where it commutes with the motion: [f, ξ_a] = Df ξ_a − Dξ_a f = 0 at
/// every state. The bracket is linear in a, so the symmetric axes are the null space of the
/// brackets of the three unit axes, taken at several states spread over the whole state space.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The world axes (orthonormal; one, or three for a free turn) about which one quaternion's body turns
/// as a symmetry of the equations of motion.
struct TurningSymmetry {
  std::size_t quaternion = 0;  // its place in quaternion_coordinates, 4 components each
  std::vector<Eigen::Vector3d> axes;
};

/// Whether quaternion k's components are cyclic (no rate depends on them: a free body's turn), so that
/// the reduced state leaves them out and every turn of it with them.
bool quaternion_is_cyclic(const eomgen_model_abi& m, std::size_t k);

/// How many quaternions the reduced state keeps (each with the zero eigenvalue of its length).
int non_cyclic_quaternions(const eomgen_model_abi& m);

/// Each quaternion's symmetric turns, tested at states spread over the state space: random
/// orientations, the other coordinates around x by a tenth of their sizes, velocities of the
/// system's `rate` (1/s; the model's default velocities' size where it is zero).
std::vector<TurningSymmetry> turning_symmetries(const Problem& problem, const std::vector<double>& x, double rate);

/// Quaternion k's components (w, x, y, z) in the state x.
Eigen::Vector4d quaternion_at(const eomgen_model_abi& m, const double* x, std::size_t k);

/// The direction in which the state x moves when quaternion k's body turns about the world axis a:
/// ½ (0, a) ⊗ q_k in q_k's components, zero elsewhere (num_states long).
Eigen::VectorXd turning_direction(const eomgen_model_abi& m, const std::vector<double>& x, std::size_t k,
                                  const Eigen::Vector3d& a);

/// "qw, qx, qy, qz about (0, 0, 1)": a symmetry in words, for reports.
std::string describe(const eomgen_model_abi& m, const TurningSymmetry& s);

/// A basis of the world axes orthogonal to `axes` (orthonormal), completing them to three.
std::vector<Eigen::Vector3d> other_axes(const std::vector<Eigen::Vector3d>& axes);

/// The (Euclidean) distance between quaternions q and p once q is turned back along the symmetry's axes as
/// far as brings it nearest p (none for three axes: every orientation is the same modulo them).
double distance_modulo_turns(const Eigen::Vector4d& q, const Eigen::Vector4d& p, const std::vector<Eigen::Vector3d>& axes);

}  // namespace eomgen::runtime
