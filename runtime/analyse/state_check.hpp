/// @file What makes a state unfit for analysis or simulation, said in the terms
/// of mechanics: quantities that are not finite there (a division by zero, a
/// function outside its domain), and a singular mass matrix with the velocities
/// that lose their inertia.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "simulation.hpp"

namespace eomgen::runtime {

/// "q1 = 0.5, der(q1) = 0" for the named state.
std::string state_text(const eomgen_model_abi& m, const std::vector<double>& x);

/// The entries of M and f, T and V that are not finite at (t, x), as "M[0][1], f[phi]";
/// empty when all are finite.
std::string non_finite_quantities(const Problem& p, double t, const std::vector<double>& x);

/// The Hessian of the kinetic energy in the state's velocities at (t, x), by polarization at zero
/// velocities, the diagonal with the given steps (one per velocity): exact, to rounding, for T
/// quadratic in them (Hamilton's T in the momenta, Appell's in the pseudo-velocities).
Eigen::MatrixXd kinetic_metric(const eomgen_model_abi& m, double t, const std::vector<double>& x,
                               const double* parameters, std::vector<double> steps);

/// The mass matrix at (t, x), num_velocities × num_velocities as the header writes it (for an
/// Appell model fewer rows than coordinates: it is the matrix of the pseudo-velocities). For a
/// Hamilton model, whose header writes p' = f with the identity, the coordinates' M, the inverse of
/// T's Hessian in the momenta (q' = M⁻¹ p): at a singularity of the coordinates (a spherical
/// pendulum's θ = 0) that Hessian grows without bound and M is singular, as it is for Lagrange II.
Eigen::MatrixXd mass_matrix_at(const Problem& p, double t, const std::vector<double>& x);

/// D M D with D_ii = 1/√m_i, m_i the larger of M_ii at x and at the model's default state (1 where
/// both are zero): M without the units of its velocities, whose eigenvalues' signs are M's
/// (Sylvester's law of inertia). A cart of 1e-9 kg carrying a pendulum of 0.5 µm has M_xx = 1.2e-9
/// and M_θθ = 5e-23, eigenvalues 14 orders apart and "singular" by any threshold on them; scaled,
/// they are 0.6 and 1.4. The default state keeps a diagonal entry that vanishes at x (a coordinate
/// singularity, such as r = 0 of polar coordinates) from being scaled back up to 1.
Eigen::MatrixXd unit_free_mass_matrix(const Problem& p, double t, const std::vector<double>& x);

struct MassMatrixRank {
  std::size_t rank = 0, size = 0;
  double smallest = 0, largest = 0;  // eigenvalues
  std::string null_velocities;       // the velocities in the directions M does not see
  bool singular() const { return rank < size; }
};

/// The rank of the (finite) mass matrix at (t, x): eigenvalues of unit_free_mass_matrix below 1e-12
/// of the largest count as zero; `smallest` and `largest` are its.
MassMatrixRank mass_matrix_rank(const Problem& p, double t, const std::vector<double>& x);

/// Why (t, x) cannot be analysed: not-finite quantities, or a singular mass matrix; empty when it can.
std::string unfit_state(const Problem& p, double t, const std::vector<double>& x);

}  // namespace eomgen::runtime
