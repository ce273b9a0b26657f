/// @file How the critical case's perturbed runs (critical_case.hpp) measure a deviation y − x from
/// the equilibrium x, so that "grew a hundredfold" means the nonlinear terms, not the units or the
/// way a linearization shares a push among its modes. In order of preference:
///  - the linearization's energy, ½ δq'ᵀ M δq' + ½ δqᵀ K δq, on Lagrange II models whose K is
///    positive definite over the non-cyclic coordinates, and ½ δsᵀ M_s δs + ½ δqᵀ K δq on Appell's
///    and Hamilton's first-order forms at rest (M_s the kinetic energy's in s, K the stiffness that
///    keeps the sum along the undamped linear motion), K positive definite over every coordinate;
///  - the linearization's modal amplitudes |V⁻¹ S⁻¹ δ| (A = V Λ V⁻¹ on the reduced state scaled by
///    the perturbations' sizes S), wherever A has a basis of eigenvectors that is well conditioned:
///    a stable linear motion does not grow in either, whatever its rates and mode shapes;
///  - each state in its own perturbation size (quaternions modulo their symmetric turns), otherwise.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analyse/linear_stability.hpp"
#include "simulation.hpp"

namespace eomgen::runtime {

class DeviationNorm {
 public:
  enum class Kind { linear_energy, modal_amplitudes, per_state };
  /// For the equilibrium x of `m` with its linear report, the states' perturbation sizes `size`
  /// (one per state of x); `parameters`, the model's, for the kinetic energy of a first-order form
  /// (without them such a form is not measured in energy).
  DeviationNorm(const eomgen_model_abi& m, const StabilityReport& report, const std::vector<double>& x,
                std::vector<double> size, const double* parameters = nullptr);
  /// The size of y − x (a state of the whole model).
  double operator()(const std::vector<double>& y) const;
  Kind kind() const { return kind_; }
  /// For the runs' report: in which measure the growth is said ("" per state).
  std::string measure() const;

 private:
  const eomgen_model_abi& m_;
  std::vector<double> x_, size_;
  std::vector<TurningSymmetry> symmetries_;
  Kind kind_ = Kind::per_state;
  std::vector<int> states_;    // the reduced state's (linear_energy: the non-cyclic coordinates)
  Eigen::MatrixXd M_, K_;      // linear_energy (M_: M_s on a first-order form)
  bool first_order_ = false;
  Eigen::MatrixXcd to_modes_;  // modal_amplitudes: V⁻¹ S⁻¹ on the reduced state
  bool use_energy(const StabilityReport& r);
  bool use_first_order_energy(const StabilityReport& r, const double* parameters);
  bool use_modes(const StabilityReport& r);
};

}  // namespace eomgen::runtime
