#include "analyse/deviation_norms.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <utility>

#include "analyse/constrained_first_order.hpp"
#include "analyse/first_order_form.hpp"
#include "analyse/state_check.hpp"
#include "analyse/turning_symmetries.hpp"

namespace eomgen::runtime {

namespace {

// Eigenvectors (unit columns) within this condition number count as a basis. A Jordan block split
// by rounding has eigenvectors parallel to within about √ε (κ near 1e8): its modal amplitudes, large
// and cancelling, would stay constant while the block's secular growth went on. 1e4 keeps clear of it.
constexpr double largest_condition = 1e4;

}  // namespace

DeviationNorm::DeviationNorm(const eomgen_model_abi& m, const StabilityReport& report, const std::vector<double>& x,
                             std::vector<double> size, const double* parameters)
    : m_(m), x_(x), size_(std::move(size)), symmetries_(report.symmetries), states_(reduced_state(m)) {
  if (use_energy(report) || use_first_order_energy(report, parameters)) kind_ = Kind::linear_energy;
  else if (use_modes(report)) kind_ = Kind::modal_amplitudes;
}

namespace {

// positive definite beyond the rounding of its eigenvalues, n ε times the largest (a margin of 64
// for the matrix's own rounding); a bound of 1e-12 had refused two oscillators at 1 and 1e6 rad/s
// (K's range exactly 1e12), measured them per state, and called them unstable
bool positive_beyond_rounding(const Eigen::MatrixXd& S) {
  Eigen::VectorXd k = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
  double rounding = 64 * double(S.rows()) * std::numeric_limits<double>::epsilon() * k.maxCoeff();
  return k.maxCoeff() > 0 && k.minCoeff() > rounding;
}

}  // namespace

// Lagrange II with K positive definite over the non-cyclic coordinates. Sizes per state had weighed
// a stiff chain's displacements against its velocities at its fastest rate, 7e4 times its slowest:
// a push's energy passed into the slow modes showed as a 3e4-fold growth.
bool DeviationNorm::use_energy(const StabilityReport& r) {
  std::size_t n = m_.num_coordinates;
  if (has_pseudo_velocities(m_) || has_multipliers(m_) || r.M.rows() != long(n) || r.K.rows() != long(n)) return false;
  std::vector<int> coordinates;
  for (std::size_t i = 0; i < n; ++i)
    if (!m_.is_cyclic[i]) coordinates.push_back(int(i));
  long c = long(coordinates.size());
  if (c == 0) return false;
  Eigen::MatrixXd K(c, c);
  for (long a = 0; a < c; ++a)
    for (long b = 0; b < c; ++b) K(a, b) = r.K(coordinates[std::size_t(a)], coordinates[std::size_t(b)]);
  if (!positive_beyond_rounding(K)) return false;
  M_ = r.M;
  K_ = K;
  states_ = coordinates;
  return true;
}

// Appell's and Hamilton's equations at rest, q' = C s and s' = A_sq q + A_ss s on the reduced state,
// every coordinate kept (C square, invertible): with the kinetic energy ½ sᵀ M_s s, the stiffness
// K = −C⁻ᵀ M_s A_sq (symmetric part) is the one for which ½ sᵀ M_s s + ½ qᵀ K q stays constant along
// the undamped linear motion (Lagrange II: C = 1, M_s = M, K = −M A_sq; Hamilton: C = M_s = M⁻¹,
// K = −∂p'/∂q). Measured per state instead, a pendulum beside a stiff damped spring written in
// either form had its velocity pushed at the spring's rate (critical_case.cpp, own_rate_pushes,
// needs this measure) and been called unstable, where written for Lagrange II it was stable.
bool DeviationNorm::use_first_order_energy(const StabilityReport& r, const double* parameters) {
  std::size_t n = m_.num_coordinates;
  long c = long(n);
  if (!parameters || !has_pseudo_velocities(m_) || has_multipliers(m_) || m_.num_velocities != n ||
      !m_.kinetic_energy || states_.size() != 2 * n || r.A.rows() != 2 * c || !r.A.allFinite())
    return false;
  for (std::size_t k = n; k < 2 * n; ++k)
    if (x_[k] != 0) return false;
  Eigen::MatrixXd C = r.A.topRightCorner(c, c), A_sq = r.A.bottomLeftCorner(c, c);
  // at rest and scleronomic, q' does not depend on q: a term there is a steady motion's or a moving
  // frame's, whose energy this is not
  double scale = std::sqrt(C.norm() * A_sq.norm());
  if (!(r.A.topLeftCorner(c, c).norm() <= 64 * double(c) * std::numeric_limits<double>::epsilon() * scale)) return false;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(C.transpose());
  if (!lu.isInvertible()) return false;
  Eigen::MatrixXd M_s = kinetic_metric(m_, 0.0, x_, parameters, std::vector<double>(size_.begin() + long(n), size_.end()));
  if (!M_s.allFinite() || !positive_beyond_rounding(M_s)) return false;
  Eigen::MatrixXd K = lu.solve(-M_s * A_sq);
  K = 0.5 * (K + K.transpose()).eval();
  if (!K.allFinite() || !positive_beyond_rounding(K)) return false;
  M_ = M_s;
  K_ = K;
  states_.resize(n);
  first_order_ = true;
  return true;
}

// A = V Λ V⁻¹ on the reduced state in units of the perturbations' sizes: the modal amplitudes
// c = V⁻¹ S⁻¹ δ of a linear motion each keep their size or shrink when no eigenvalue is to the right,
// so |c| grows only by the nonlinear terms. Per-state sizes had measured the Clohessy–Wiltshire
// drift's along-track velocity, which a radial push sets going, in the size of the cyclic coordinate's
// default 1e-3: a bounded motion "grew" 120-fold. Quaternions keep their norm modulo turns instead.
bool DeviationNorm::use_modes(const StabilityReport& r) {
  if (m_.num_quaternions > 0 || has_multipliers(m_)) return false;
  long n = long(states_.size());
  if (n == 0 || r.A.rows() != n || r.A.cols() != n || !r.A.allFinite()) return false;
  Eigen::VectorXd s(n);
  for (long i = 0; i < n; ++i) s[i] = size_[std::size_t(states_[std::size_t(i)])];
  if (!(s.minCoeff() > 0) || !s.allFinite()) return false;
  Eigen::MatrixXd scaled = s.cwiseInverse().asDiagonal() * r.A * s.asDiagonal();
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(scaled);
  if (eigen.info() != Eigen::Success) return false;
  Eigen::MatrixXcd V = eigen.eigenvectors();
  Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXcd>(V).singularValues();
  if (!(sigma[n - 1] * largest_condition > sigma[0])) return false;
  to_modes_ = V.partialPivLu().inverse() * s.cwiseInverse().cast<std::complex<double>>().asDiagonal();
  return true;
}

double DeviationNorm::operator()(const std::vector<double>& y) const {
  switch (kind_) {
    case Kind::linear_energy: {
      std::size_t n = m_.num_coordinates;
      Eigen::VectorXd dv(static_cast<long>(n)), dq(static_cast<long>(states_.size()));
      for (std::size_t i = 0; i < n; ++i) dv[long(i)] = y[n + i] - x_[n + i];
      for (std::size_t a = 0; a < states_.size(); ++a) dq[long(a)] = y[std::size_t(states_[a])] - x_[std::size_t(states_[a])];
      return std::sqrt(0.5 * dv.dot(M_ * dv) + 0.5 * dq.dot(K_ * dq));
    }
    case Kind::modal_amplitudes: {
      Eigen::VectorXcd d(static_cast<long>(states_.size()));
      for (std::size_t a = 0; a < states_.size(); ++a) d[long(a)] = y[std::size_t(states_[a])] - x_[std::size_t(states_[a])];
      return (to_modes_ * d).norm();
    }
    case Kind::per_state: break;
  }
  // each state in its own size; a quaternion with symmetric turns by its distance from x's once
  // turned back along them (its smallest size)
  std::vector<bool> turned(m_.num_states, false);
  double d = 0;
  for (const TurningSymmetry& s : symmetries_) {
    const std::size_t* c = m_.quaternion_coordinates + 4 * s.quaternion;
    Eigen::Vector4d q = quaternion_at(m_, y.data(), s.quaternion), p = quaternion_at(m_, x_.data(), s.quaternion);
    double smallest = std::min(std::min(size_[c[0]], size_[c[1]]), std::min(size_[c[2]], size_[c[3]]));
    d = std::max(d, distance_modulo_turns(q, p, s.axes) / smallest);
    for (int j = 0; j < 4; ++j) turned[c[j]] = true;
  }
  for (int i : states_) {
    auto k = static_cast<std::size_t>(i);
    if (!turned[k]) d = std::max(d, std::abs(y[k] - x_[k]) / size_[k]);
  }
  return d;
}

std::string DeviationNorm::measure() const {
  switch (kind_) {
    case Kind::linear_energy:
      return first_order_ ? " in the linearization's energy, ½ δsᵀ M_s δs + ½ δqᵀ K δq (M_s the kinetic energy's in the "
                            "velocities s, K positive definite)"
                          : " in the linearization's energy, ½ δq'ᵀ M δq' + ½ δqᵀ K δq (K positive definite)";
    case Kind::modal_amplitudes: return " in the linearization's modal amplitudes, |V⁻¹ δ| for A = V Λ V⁻¹";
    case Kind::per_state: break;
  }
  return "";
}

}  // namespace eomgen::runtime
