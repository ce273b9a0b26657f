#include "derive/articulated_inverse_dynamics.hpp"

#include <fmt/format.h>

#include "derive/recursion_quantities.hpp"
#include "kinematics/vector3.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

class InverseDynamics {
 public:
  InverseDynamics(const Model& model, const Mechanics& mechanics, const ParticleTree& tree,
                  const ArticulatedAccelerations& forward, const std::vector<GiNaC::symbol>& accelerations,
                  std::vector<Intermediate>& intermediates)
      : model_(model), mechanics_(mechanics), tree_(tree), forward_(forward), ddq_(accelerations),
        count_(model.particles.size()), name_(intermediates),
        joint_of_(tree.joints_of_coordinates(model.symbols.num_coordinates())) {}

  TreeInverseDynamics run() {
    std::size_t n = joint_of_.size();
    for (std::size_t j = 0; j < n; ++j) out_.axes.push_back(forward_.motions[joint_of_[j].first].axes[joint_of_[j].second]);
    composite_masses();
    coordinate_tree();
    subtree_forces();
    relative_acceleration_derivatives();
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t l = 0; l < n; ++l) out_.coupling.push_back(tree_.coupling(joint_of_[j].first, joint_of_[l].first));
    const Symbols& s = model_.symbols;
    std::vector<ex> variables(s.coordinates.begin(), s.coordinates.end());
    variables.insert(variables.end(), s.velocities.begin(), s.velocities.end());
    variables.insert(variables.end(), s.inputs.begin(), s.inputs.end());
    for (std::size_t j = 0; j < n; ++j) {
      ex Q = applied_generalized_force(model_, mechanics_, j);
      out_.forcing.push_back(Q - dot(out_.axes[j], rest_force_[joint_of_[j].first]));
      gradient_rest(j, gradient(Q, variables));
    }
    return out_;
  }

 private:
  // m̄_i = m_i + Σ m̄_child, leaves first
  void composite_masses() {
    std::vector<ex>& mass = out_.subtree_masses;
    for (std::size_t i = 0; i < count_; ++i) mass.push_back(model_.particles[i].mass);
    for (std::size_t at = count_; at-- > 0;) {
      std::size_t i = tree_.order[at];
      mass[i] = name_(mass[i], fmt::format("ab{}_mass", i));
      if (int parent = tree_.joints[i].parent; parent >= 0) mass[std::size_t(parent)] += mass[i];
    }
  }

  // each particle's joint as a chain of one-coordinate joints, the mass on the last (the recursion
  // gives the same q'' either way: D = SᵀIA S eliminated one column of S at a time)
  void coordinate_tree() {
    std::size_t n = joint_of_.size();
    out_.coordinate_parent.assign(n, -1);
    out_.carried_masses.assign(n, ex(0));
    out_.joint_carrier.assign(n, 0);
    std::vector<int> carrier(count_, -1);  // the coordinate that carries each particle's mass
    for (std::size_t i : tree_.order) {
      int parent = tree_.joints[i].parent, above = parent < 0 ? -1 : carrier[std::size_t(parent)];
      for (std::size_t j : tree_.joints[i].coordinates) {
        out_.coordinate_order.push_back(j);
        out_.coordinate_parent[j] = above;
        above = int(j);
      }
      carrier[i] = above;
      for (std::size_t j : tree_.joints[i].coordinates) out_.joint_carrier[j] = std::size_t(above);
      if (above >= 0) out_.carried_masses[std::size_t(above)] += model_.particles[i].mass;
    }
  }

  // a_i = a_parent + c_i + S_i q_J'' from the root (q'' held, and at rest), then
  // F_i = m_i (a_i − g) + Σ F_child from the leaves
  void subtree_forces() {
    std::vector<Vector3> held(count_), rest(count_);
    for (std::size_t i : tree_.order) {
      const RelativeMotion& m = forward_.motions[i];
      int parent = tree_.joints[i].parent;
      Vector3 base = parent < 0 ? Vector3{0, 0, 0} : held[std::size_t(parent)];
      Vector3 base_at_rest = parent < 0 ? Vector3{0, 0, 0} : rest[std::size_t(parent)];
      Vector3 a = base + m.bias;
      for (std::size_t b = 0; b < m.axes.size(); ++b) a = a + scaled(ddq_[tree_.joints[i].coordinates[b]], m.axes[b]);
      held[i] = name_(a, fmt::format("ab{}_acc", i));
      rest[i] = name_(base_at_rest + m.bias, fmt::format("ab{}_rest", i));
    }
    force_.assign(count_, Vector3{0, 0, 0});
    rest_force_.assign(count_, Vector3{0, 0, 0});
    for (std::size_t at = count_; at-- > 0;) {
      std::size_t i = tree_.order[at];
      const ex& m = model_.particles[i].mass;
      force_[i] = name_(force_[i] + scaled(m, held[i] - model_.gravity), fmt::format("ab{}_force", i));
      rest_force_[i] = name_(rest_force_[i] + scaled(m, rest[i] - model_.gravity), fmt::format("ab{}_restforce", i));
      if (int parent = tree_.joints[i].parent; parent >= 0) {
        force_[std::size_t(parent)] = force_[std::size_t(parent)] + force_[i];
        rest_force_[std::size_t(parent)] = rest_force_[std::size_t(parent)] + rest_force_[i];
      }
    }
  }

  // ∂d_i''/∂q_l = Σ ∂S/∂q_l q_J'' + ∂c/∂q_l and ∂d_i''/∂q'_l = ∂c/∂q'_l, for the coordinates l of joint i
  void relative_acceleration_derivatives() {
    const Symbols& s = model_.symbols;
    for (std::size_t l = 0; l < joint_of_.size(); ++l) {
      auto [i, b] = joint_of_[l];
      const RelativeMotion& m = forward_.motions[i];
      const std::vector<std::size_t>& J = tree_.joints[i].coordinates;
      Vector3 dq{0, 0, 0}, dv{0, 0, 0};
      for (unsigned d = 0; d < 3; ++d) {
        dq[d] = m.bias_expression[d].diff(s.coordinates[l]);
        dv[d] = m.bias_expression[d].diff(s.velocities[l]);
        for (std::size_t c = 0; c < J.size(); ++c) dq[d] += m.axis_expressions[c][d].diff(s.coordinates[l]) * ddq_[J[c]];
      }
      out_.acceleration_by_coordinate.push_back(name_(dq, fmt::format("ab{}_Aq{}_", i, b)));
      out_.acceleration_by_velocity.push_back(name_(dv, fmt::format("ab{}_Av{}_", i, b)));
    }
  }

  // the terms of ∂τ_j/∂(q, q', u) besides m̄ S_j · ∂d''/∂x: ∂S_j/∂q_l · F_i within the joint, −∂Q_j/∂x
  // (`applied_gradient`: ∂Q_j/∂(q, q', u))
  void gradient_rest(std::size_t j, const std::vector<ex>& applied_gradient) {
    const Symbols& s = model_.symbols;
    auto [i, b] = joint_of_[j];
    const Vector3& raw = forward_.motions[i].axis_expressions[b];
    for (std::size_t k = 0; k < applied_gradient.size(); ++k) {
      ex term = -applied_gradient[k];
      if (k < joint_of_.size() && joint_of_[k].first == i) {
        const GiNaC::realsymbol& q = s.coordinates[k];
        term += dot({raw[0].diff(q), raw[1].diff(q), raw[2].diff(q)}, force_[i]);
      }
      out_.gradient_rest.push_back(term);
    }
  }

  const Model& model_;
  const Mechanics& mechanics_;
  const ParticleTree& tree_;
  const ArticulatedAccelerations& forward_;
  const std::vector<GiNaC::symbol>& ddq_;
  std::size_t count_;
  RecursionQuantities name_;
  std::vector<std::pair<std::size_t, std::size_t>> joint_of_;  // coordinate → (particle, place in its joint)
  std::vector<Vector3> force_, rest_force_;                      // F_i with q'' held, and at q'' = 0
  TreeInverseDynamics out_;
};

}  // namespace

TreeInverseDynamics articulated_inverse_dynamics(const Model& model, const Mechanics& mechanics, const ParticleTree& tree,
                                                 const ArticulatedAccelerations& forward,
                                                 const std::vector<GiNaC::symbol>& accelerations,
                                                 std::vector<Intermediate>& intermediates) {
  return InverseDynamics(model, mechanics, tree, forward, accelerations, intermediates).run();
}

}  // namespace eomgen
