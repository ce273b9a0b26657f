#include "analyse/turning_symmetries.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "analyse/first_order_form.hpp"
#include "integrate/coordinate_sizes.hpp"

namespace eomgen::runtime {

namespace {

// (0, a) ⊗ q = (−a·v, w a + a × v) for q = (w, v)
Eigen::Vector4d axis_times(const Eigen::Vector3d& a, const Eigen::Vector4d& q) {
  Eigen::Vector3d v = q.tail<3>();
  Eigen::Vector4d out;
  out[0] = -a.dot(v);
  out.tail<3>() = q[0] * a + a.cross(v);
  return out;
}

// States spread over the state space for the bracket: every quaternion a random orientation, the
// other coordinates around x by a tenth of their sizes, every velocity of the size `speed`
std::vector<std::vector<double>> sample_states(const eomgen_model_abi& m, const std::vector<double>& x, double speed) {
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  std::vector<double> size = coordinate_sizes(m, x.data(), true, 1.0);
  std::vector<std::vector<double>> states;
  for (int s = 0; s < 6; ++s) {
    std::vector<double> y = x;
    for (std::size_t i = 0; i < m.num_coordinates; ++i) y[i] += 0.1 * size[i] * normal(random);
    for (std::size_t k = 0; k < m.num_quaternions; ++k) {
      Eigen::Vector4d q;
      for (int c = 0; c < 4; ++c) q[c] = normal(random);
      q.normalize();
      for (int c = 0; c < 4; ++c) y[m.quaternion_coordinates[4 * k + std::size_t(c)]] = q[c];
    }
    for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) y[i] = speed * normal(random);
    states.push_back(y);
  }
  return states;
}

// The brackets [f, ξ_a] of quaternion k's three unit axes at the sample states, each state's rows of
// coordinates and of velocities over the largest of the terms that cancel in them (Df ξ_a and
// Dξ_a f = ½ (0, a) ⊗ q'): a symmetric axis leaves only their rounding. Rows: states × samples.
Eigen::MatrixXd scaled_brackets(const Problem& p, const std::vector<std::vector<double>>& samples, std::size_t k) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_states;
  Eigen::MatrixXd brackets(long(n * samples.size()), 3), terms(long(n * samples.size()), 3);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const std::vector<double>& y = samples[s];
    std::vector<double> f(n);
    m.rhs(0.0, y.data(), p.held_inputs(), p.parameters.data(), f.data());
    Eigen::MatrixXd J = state_jacobian(p, 0.0, y);
    for (int axis = 0; axis < 3; ++axis) {
      Eigen::Vector3d a = Eigen::Vector3d::Unit(axis);
      // Dξ_a f: the turn's direction taken of the quaternion's rate, ξ_a being linear in q
      Eigen::VectorXd along = J * turning_direction(m, y, k, a), carried = turning_direction(m, f, k, a);
      brackets.block(long(s * n), axis, long(n), 1) = along - carried;
      terms.block(long(s * n), axis, long(n), 1) = along.cwiseAbs() + carried.cwiseAbs();
    }
  }
  // coordinates' rows and velocities' rows have their own units: each group over its own largest term
  for (std::size_t s = 0; s < samples.size(); ++s)
    for (auto [from, to] : {std::pair{std::size_t(0), m.num_coordinates}, std::pair{m.num_coordinates, n}}) {
      if (to == from) continue;
      double largest = terms.block(long(s * n + from), 0, long(to - from), 3).maxCoeff();
      brackets.block(long(s * n + from), 0, long(to - from), 3) /= largest > 0 ? largest : 1.0;
    }
  return brackets;
}

// the brackets' relative size below which an axis is symmetric: rounding leaves about 1e-15 of the
// cancelling terms; a symmetry broken by a part in 1e8 or more is seen
constexpr double symmetric_below = 1e-8;

}  // namespace

bool quaternion_is_cyclic(const eomgen_model_abi& m, std::size_t k) {
  const std::size_t* c = m.quaternion_coordinates + 4 * k;
  return m.is_cyclic[c[0]] || m.is_cyclic[c[1]] || m.is_cyclic[c[2]] || m.is_cyclic[c[3]];
}

int non_cyclic_quaternions(const eomgen_model_abi& m) {
  int kept = 0;
  for (std::size_t k = 0; k < m.num_quaternions; ++k) kept += !quaternion_is_cyclic(m, k);
  return kept;
}

Eigen::Vector4d quaternion_at(const eomgen_model_abi& m, const double* x, std::size_t k) {
  Eigen::Vector4d q;
  for (int c = 0; c < 4; ++c) q[c] = x[m.quaternion_coordinates[4 * k + std::size_t(c)]];
  return q;
}

Eigen::VectorXd turning_direction(const eomgen_model_abi& m, const std::vector<double>& x, std::size_t k,
                                  const Eigen::Vector3d& a) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(long(m.num_states));
  Eigen::Vector4d turned = 0.5 * axis_times(a, quaternion_at(m, x.data(), k));
  for (int c = 0; c < 4; ++c) d[long(m.quaternion_coordinates[4 * k + std::size_t(c)])] = turned[c];
  return d;
}

std::vector<TurningSymmetry> turning_symmetries(const Problem& problem, const std::vector<double>& x, double rate) {
  const eomgen_model_abi& m = *problem.model;
  std::vector<TurningSymmetry> found;
  if (m.num_quaternions == 0 || !has_pseudo_velocities(m)) return found;
  double speed = rate;
  for (std::size_t i = m.num_coordinates; i < m.num_states && !(speed > 0); ++i)
    speed = std::max(speed, std::abs(m.default_state[i]));
  std::vector<std::vector<double>> samples = sample_states(m, x, speed > 0 ? speed : 1.0);
  for (std::size_t k = 0; k < m.num_quaternions; ++k) {
    if (quaternion_is_cyclic(m, k)) continue;  // out of the reduced state already
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled_brackets(problem, samples, k), Eigen::ComputeFullV);
    TurningSymmetry s{k, {}};
    for (int j = 0; j < 3; ++j)
      if (!(svd.singularValues()[j] > symmetric_below)) s.axes.push_back(svd.matrixV().col(j).normalized());
    // two symmetric axes turn about a third too (their commutator): a free turn
    if (s.axes.size() == 2) s.axes = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
    if (!s.axes.empty()) found.push_back(s);
  }
  return found;
}

std::string describe(const eomgen_model_abi& m, const TurningSymmetry& s) {
  std::string names;
  for (int c = 0; c < 4; ++c) names += fmt::format("{}{}", c ? ", " : "", m.coordinate_names[m.quaternion_coordinates[4 * s.quaternion + std::size_t(c)]]);
  if (s.axes.size() == 3) return names + " turned about every axis";
  const Eigen::Vector3d& a = s.axes[0];
  // the sign of an axis is a matter of choice: its largest component positive
  Eigen::Index largest;
  a.cwiseAbs().maxCoeff(&largest);
  Eigen::Vector3d shown = a[largest] < 0 ? Eigen::Vector3d(-a) : a;
  auto entry = [](double v) { return std::abs(v) < 1e-12 ? std::string("0") : fmt::format("{:.6g}", v); };
  return fmt::format("{} turned about the world axis ({}, {}, {})", names, entry(shown[0]), entry(shown[1]), entry(shown[2]));
}

std::vector<Eigen::Vector3d> other_axes(const std::vector<Eigen::Vector3d>& axes) {
  Eigen::Matrix3d basis = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < axes.size() && i < 3; ++i) basis.col(long(i)) = axes[i];
  Eigen::HouseholderQR<Eigen::Matrix3d> qr(basis);
  Eigen::Matrix3d Q = qr.householderQ();
  std::vector<Eigen::Vector3d> others;
  for (std::size_t i = axes.size(); i < 3; ++i) others.push_back(Q.col(long(i)));
  return others;
}

double distance_modulo_turns(const Eigen::Vector4d& q, const Eigen::Vector4d& p, const std::vector<Eigen::Vector3d>& axes) {
  if (axes.size() >= 3) return 0;
  if (axes.empty()) return (q - p).norm();
  // r(θ) ⊗ p = cos(θ/2) p + sin(θ/2) (0, a) ⊗ p: nearest q where θ/2 = atan2(q·((0, a) ⊗ p), q·p)
  Eigen::Vector4d turned = axis_times(axes[0], p);
  double half = std::atan2(q.dot(turned), q.dot(p));
  return (q - (std::cos(half) * p + std::sin(half) * turned)).norm();
}

}  // namespace eomgen::runtime
