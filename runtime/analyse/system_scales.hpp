/// @file The system's own scales, against which a verdict decides what is zero. A
/// tolerance in absolute units (1e-9, or 1e-9 times max(1, |A|)) calls the damping of a
/// MEMS resonator (eigenvalues −5 ± 1e5 i, |A| = 1e10) zero and that of a slow system
/// anything at all; relative to these scales, a verdict does not change when the system
/// is scaled in time or in units.
#pragma once

#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace eomgen::runtime {

/// A real part within this fraction of the spectral scale counts as on the imaginary axis.
inline constexpr double relative_axis_tolerance = 1e-9;
/// Eigenvalues within this fraction of the spectral scale count as one (a double root, or a
/// Jordan block, splits by about √ε of the scale in rounding).
inline constexpr double relative_cluster_tolerance = 1e-6;

/// The diagonal of D (powers of two, so exact) that makes each state's row and column of
/// D⁻¹ A D comparable (Parlett and Reinsch): the same eigenvalues, entries on their scale.
Eigen::VectorXd balancing_scales(const Eigen::MatrixXd& A);
/// D⁻¹ A D with D from balancing_scales.
Eigen::MatrixXd balanced(const Eigen::MatrixXd& A);
/// A's eigenvalues, computed on the balanced A: Eigen's solver does not balance, and a
/// two-mass oscillator at 1e7 rad/s (A's entries from 1 to 1e14) lost 1 % of them.
std::vector<std::complex<double>> balanced_eigenvalues(const Eigen::MatrixXd& A);

/// The size of A's eigenvalue problem in A's own units: the largest entry of the balanced
/// A (0 only for A = 0). A scales with time as the eigenvalues do, and a change of units
/// of the states, a diagonal similarity, leaves it unchanged.
double spectral_scale(const Eigen::MatrixXd& A);

/// The scale that decides which eigenvalues are zero or equal: the spectral radius of the
/// balanced A, but no less than 1e-6 of its largest entry. Not the largest entry alone: a
/// triangular A keeps entries far above its eigenvalues whatever the balancing (an
/// eigenvalue −1e10 beside an entry 1.4e17), and clustering against them merged 0 and −1e10.
double eigenvalue_scale(const Eigen::MatrixXd& balanced_A, const std::vector<std::complex<double>>& eigenvalues);

/// The fastest and the slowest rate of A: the largest |λ|, and the smallest |λ| above
/// relative_cluster_tolerance of it (rigid-body modes and cyclic coordinates, λ = 0, set no time
/// scale); both 0 where every λ is 0, NaN where A is not finite. The step and the damping of a
/// come-to-rest search take them.
struct RateRange {
  double fastest = 0, slowest = 0;
};
RateRange rate_range(const Eigen::MatrixXd& A);

/// M q'' + D q' + G q' + K q + N q = 0 in mass-normalized coordinates M^½ q: the matrices
/// L X L with L = M^−½, rates D', G' in 1/s and stiffnesses K', N' in 1/s², and the
/// system's rate, max(√|K'|, |D'|, |G'|, √|N'|) with |·| the largest entry.
struct MassNormalized {
  Eigen::MatrixXd K, D, G, N;
  double rate = 0;
};
MassNormalized mass_normalized(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& D,
                               const Eigen::MatrixXd& G, const Eigen::MatrixXd& N);

}  // namespace eomgen::runtime
