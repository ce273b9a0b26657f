/// @file Stability of an equilibrium from its linearization (Hiller §5.3, §7,
/// §8): M q'' + (D + G) q' + (K + N) q = B u, the state matrix A of the reduced
/// system (positions of cyclic coordinates dropped), its eigenvalues, the
/// verdict, the modes, the characteristic polynomial with its Hurwitz
/// determinants, the classical results on the force structure, and the
/// phase-plane type of a two-state system.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analyse/turning_symmetries.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

struct Mode {
  std::complex<double> eigenvalue;
  double frequency;             // damped frequency |Im λ|, rad/s
  double undamped_frequency;    // |λ|, rad/s: the natural frequency ω0 of λ² + 2ζω0 λ + ω0²
  double damping_ratio;         // ζ = −Re λ / |λ| (1 for a real negative eigenvalue, 0 on the imaginary axis)
};

struct StabilityReport {
  std::vector<std::string> state_names;  // of the reduced state
  Eigen::MatrixXd M, P, Q, D, G, K, N, B;  // second-order form, all coordinates
  Eigen::MatrixXd A, B_state;              // reduced first-order form
  std::vector<std::complex<double>> eigenvalues;  // sorted by decreasing real part
  /// those that count for the verdict: without the zeros left out, and of A modulo the turns that are
  /// symmetries where there are any (a Jordan block's pair, split by rounding into ±1e-8 of the
  /// system's rate, had set the perturbed runs' length to 200 of its "periods": 8e22 s)
  std::vector<std::complex<double>> counted_eigenvalues;
  std::string verdict;                            // asymptotically_stable | marginally_stable | unstable | undecided
  /// Why the verdict is `undecided`: the eigenvalues and a theorem whose hypotheses hold disagree
  /// (see reconcile_with_theorems); empty otherwise.
  std::string disagreement;
  double stability_degree = 0;                    // largest real part that counts for the verdict
  int cyclic_zero_eigenvalues = 0;                // zero eigenvalues of conserved cyclic momenta, left out
  int quaternion_zero_eigenvalues = 0;            // zero eigenvalues of the quaternions' lengths, left out
  /// zero eigenvalues of turns that are symmetries (turning_symmetries.hpp), two per turning axis
  /// (the orbit's and its momentum's), left out: the verdict is with respect to the rest
  int symmetry_zero_eigenvalues = 0;
  std::vector<TurningSymmetry> symmetries;
  std::vector<std::string> symmetry_names;        // each in words (describe)
  double axis_tolerance = 0;                      // a real part within it is on the imaginary axis (system_scales.hpp)
  std::vector<Mode> modes;                        // by undamped frequency, then damped frequency
  std::vector<double> characteristic_polynomial;  // det(λI − A), highest power first (leading 1)
  /// Leading principal minors of the Hurwitz matrix of the polynomial in μ = λ/s, where
  /// s = |a_n|^(1/n) balances the coefficients (the signs, which decide, do not change);
  /// a minor within rounding of zero is reported as 0, or NaN when no pair of eigenvalues
  /// λ, −λ explains a zero (then its sign is lost in rounding).
  std::vector<double> hurwitz;
  double hurwitz_scale = 1;                       // s
  bool hurwitz_ill_conditioned = false;           // a minor's sign is lost in rounding: the eigenvalues decide
  std::vector<std::string> theorems;
  std::string phase_plane;                        // two-state systems only
};

/// Holds the eigenvalue verdict against the theorems the force structure decided: a theorem
/// whose hypotheses hold and that says otherwise makes the verdict `undecided`, with both named
/// in `disagreement`, instead of one of them being printed beside the other as if both held.
void reconcile_with_theorems(StabilityReport& report);

/// Analyses the equilibrium x (from find_equilibrium or check_equilibrium).
StabilityReport analyse_stability(const Problem& problem, const std::vector<double>& x);

/// The reduced system's eigenvalues that count for the verdict (the zeros of conserved
/// cyclic momenta left out), sorted by decreasing real part, with the verdict, the
/// stability degree and the tolerance within which a real part counts as zero.
struct CountedSpectrum {
  std::vector<std::complex<double>> eigenvalues;
  std::string verdict;
  double degree = 0, tolerance = 0;
  std::vector<double> errors;  // each eigenvalue's own rounding, ε·|A|·κ (κ its condition number)
};
CountedSpectrum counted_spectrum(const Problem& problem, const std::vector<double>& x);
/// The same for a given first-order matrix A with `cyclic` zero eigenvalues of conserved
/// momenta to leave out.
CountedSpectrum counted_spectrum(const Eigen::MatrixXd& A, int cyclic = 0);

/// Only the largest real part of the reduced system's eigenvalues that counts for the
/// verdict: the quantity of a stability map.
double stability_degree(const Problem& problem, const std::vector<double>& x);

/// Π (λ − r_i) expanded, highest power first; real parts, with coefficients within the
/// rounding of the roots' symmetric functions set to 0.
std::vector<double> polynomial_from_roots(const std::vector<std::complex<double>>& roots);

/// Hurwitz determinants of a polynomial given highest power first.
std::vector<double> hurwitz_determinants(const std::vector<double>& coefficients);

struct ScaledHurwitz {
  std::vector<double> minors;  // of the polynomial in λ/scale; 0 where within rounding
  double scale = 1;
  bool ill_conditioned = false;  // a nonzero minor is within rounding of zero
};
/// The Hurwitz determinants of the balanced polynomial, with the rounding of each
/// bounded by Hadamard's inequality.
ScaledHurwitz scaled_hurwitz_determinants(const std::vector<double>& coefficients);

/// The classification of x' = A x for 2×2 A (node, focus, saddle, centre, ...).
std::string phase_plane_type(const Eigen::Matrix2d& A);

}  // namespace eomgen::runtime
