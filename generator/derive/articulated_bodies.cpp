#include "derive/articulated_bodies.hpp"

#include <fmt/format.h>

#include "derive/recursion_quantities.hpp"
#include "kinematics/vector3.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::matrix;

namespace {

class Recursion {
 public:
  Recursion(const Model& model, const Mechanics& mechanics, const ParticleTree& tree)
      : model_(model), mechanics_(mechanics), tree_(tree), count_(model.particles.size()) {}

  ArticulatedAccelerations run() {
    out_.accelerations.assign(model_.symbols.num_coordinates(), 0);
    out_.motions.resize(count_);
    inward();
    outward();
    solve();
    return out_;
  }

 private:
  // one joint's quantities, kept from the inward pass for the outward one
  struct Joint {
    matrix S{3, 1}, U{3, 1}, D_inverse{1, 1}, W{3, 1};
    Vector3 c{0, 0, 0};
    std::vector<ex> u;  // Q − Sᵀ pA
  };

  // S = ∂d/∂q_J and c = d''(q'' = 0) of particle i's displacement from its parent
  void joint_motion(std::size_t i, Joint& J) {
    JointMotion raw = eomgen::joint_motion(tree_.joints[i], model_.symbols);
    std::size_t k = raw.axes.size();
    J.S = matrix(3, unsigned(k));
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < k; ++b) J.S(a, b) = raw.axes[b][a];
    J.c = raw.bias;
    RelativeMotion& motion = out_.motions[i];
    for (unsigned b = 0; b < k; ++b) motion.axis_expressions.push_back(column(J.S, b));
    motion.bias_expression = J.c;
    std::string p = fmt::format("ab{}_", i);
    J.S = named_(J.S, p + "S", false);
    J.c = named_(J.c, p + "c");
    for (unsigned b = 0; b < k; ++b) motion.axes.push_back(column(J.S, b));
    motion.bias = J.c;
  }

  // leaves to root: IA_i = m_i 1 + Σ Ia_child, pA_i = −m_i g + Σ pa_child (each parent after its children)
  void inward() {
    inertia_.assign(count_, matrix(3, 3));
    bias_force_.assign(count_, Vector3{0, 0, 0});
    for (std::size_t i = 0; i < count_; ++i) {
      const Particle& p = model_.particles[i];
      for (unsigned a = 0; a < 3; ++a) inertia_[i](a, a) = p.mass, bias_force_[i][a] = -p.mass * model_.gravity[a];
    }
    joints_.resize(count_);
    for (std::size_t at = count_; at-- > 0;) articulate(tree_.order[at]);
  }

  // particle i's joint: U = IA S, D = Sᵀ U, u = Q − Sᵀ pA, and what its subtree hands to the parent,
  // Ia = IA − U D⁻¹ Uᵀ and pa = pA + Ia c + U D⁻¹ u (IA and pA themselves for a joint without coordinates)
  void articulate(std::size_t i) {
    std::string p = fmt::format("ab{}_", i);
    matrix I = named_(inertia_[i], p + "I", true);
    Vector3 pA = named_(bias_force_[i], p + "p");
    Joint& J = joints_[i];
    std::size_t k = tree_.joints[i].coordinates.size();
    if (k == 0) return hand_to_parent(i, I, pA);
    joint_motion(i, J);
    J.U = named_(I.mul(J.S), p + "U", false);
    matrix D = named_(J.S.transpose().mul(J.U), p + "D", true);
    J.D_inverse = named_(D.inverse(), p + "Di", true);
    for (unsigned b = 0; b < k; ++b) {
      ex u = applied_generalized_force(model_, mechanics_, tree_.joints[i].coordinates[b]);
      for (unsigned a = 0; a < 3; ++a) u -= J.S(a, b) * pA[a];
      J.u.push_back(named_(u, p + fmt::format("u{}", b)));
    }
    if (tree_.joints[i].parent < 0) return;
    J.W = named_(J.U.mul(J.D_inverse), p + "W", false);
    const matrix& W = J.W;
    matrix Ia = I;
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b)
        for (unsigned l = 0; l < k; ++l) Ia(a, b) -= W(a, l) * J.U(b, l);
    Ia = named_(Ia, p + "Ia", true);
    Vector3 pa = pA;
    for (unsigned a = 0; a < 3; ++a) {
      for (unsigned b = 0; b < 3; ++b) pa[a] += Ia(a, b) * J.c[b];
      for (unsigned l = 0; l < k; ++l) pa[a] += W(a, l) * J.u[l];
    }
    hand_to_parent(i, Ia, pa);
  }

  void hand_to_parent(std::size_t i, const matrix& Ia, const Vector3& pa) {
    int parent = tree_.joints[i].parent;
    if (parent < 0) return;
    for (unsigned a = 0; a < 3; ++a) {
      bias_force_[std::size_t(parent)][a] += pa[a];
      for (unsigned b = 0; b < 3; ++b) inertia_[std::size_t(parent)](a, b) += Ia(a, b);
    }
  }

  // root to leaves: q_J'' = D⁻¹ (u − Uᵀ (a_parent + c)), a_i = a_parent + c + S q_J''
  void outward() {
    std::vector<Vector3> acceleration(count_, Vector3{0, 0, 0});
    for (std::size_t i : tree_.order) {
      const Joint& J = joints_[i];
      const ParticleJoint& pj = tree_.joints[i];
      std::string p = fmt::format("ab{}_", i);
      Vector3 base = (pj.parent < 0 ? Vector3{0, 0, 0} : acceleration[std::size_t(pj.parent)]) + J.c;
      std::size_t k = pj.coordinates.size();
      if (k == 0) {
        acceleration[i] = base;
        continue;
      }
      std::vector<ex> rhs(k), ddq(k);
      for (unsigned l = 0; l < k; ++l) {
        rhs[l] = J.u[l];
        for (unsigned a = 0; a < 3; ++a) rhs[l] -= J.U(a, l) * base[a];
        rhs[l] = named_(rhs[l], p + fmt::format("r{}", l));
      }
      for (unsigned l = 0; l < k; ++l) {
        ex sum = 0;
        for (unsigned b = 0; b < k; ++b) sum += J.D_inverse(l, b) * rhs[b];
        ddq[l] = named_(sum, p + fmt::format("ddq{}", l));
        out_.accelerations[pj.coordinates[l]] = ddq[l];
      }
      Vector3 a = base;
      for (unsigned d = 0; d < 3; ++d)
        for (unsigned l = 0; l < k; ++l) a[d] += J.S(d, l) * ddq[l];
      acceleration[i] = named_(a, p + "a");
    }
  }

  // q'' = M⁻¹ b for generalized forces b given as symbols: the two passes again without gravity,
  // velocities and other forces (pA = 0, c = 0, Q = b), through the joints' S, U, D⁻¹ and W
  void solve() {
    std::size_t n = model_.symbols.num_coordinates();
    for (std::size_t j = 0; j < n; ++j) out_.forces.emplace_back(fmt::format("b{}", j));
    out_.accelerations_of_forces.assign(n, 0);
    std::vector<Vector3> handed(count_, Vector3{0, 0, 0});
    std::vector<std::vector<ex>> u(count_);
    for (std::size_t at = count_; at-- > 0;) {
      std::size_t i = tree_.order[at];
      const ParticleJoint& pj = tree_.joints[i];
      const Joint& J = joints_[i];
      std::string p = fmt::format("ab{}_b", i);
      Vector3 pA = named_(handed[i], p + "p");
      for (unsigned l = 0; l < pj.coordinates.size(); ++l) {
        ex ul = out_.forces[pj.coordinates[l]];
        for (unsigned a = 0; a < 3; ++a) ul -= J.S(a, l) * pA[a];
        u[i].push_back(named_(ul, p + fmt::format("u{}", l)));
      }
      if (pj.parent < 0) continue;
      for (unsigned a = 0; a < 3; ++a) {
        ex pa = pA[a];
        for (unsigned l = 0; l < u[i].size(); ++l) pa += J.W(a, l) * u[i][l];
        handed[std::size_t(pj.parent)][a] += pa;
      }
    }
    std::vector<Vector3> acceleration(count_, Vector3{0, 0, 0});
    for (std::size_t i : tree_.order) {
      const ParticleJoint& pj = tree_.joints[i];
      const Joint& J = joints_[i];
      Vector3 a = pj.parent < 0 ? Vector3{0, 0, 0} : acceleration[std::size_t(pj.parent)];
      std::size_t k = pj.coordinates.size();
      std::vector<ex> r(k);
      for (unsigned l = 0; l < k; ++l) {
        r[l] = u[i][l];
        for (unsigned d = 0; d < 3; ++d) r[l] -= J.U(d, l) * a[d];
      }
      for (unsigned l = 0; l < k; ++l) {
        ex sum = 0;
        for (unsigned c = 0; c < k; ++c) sum += J.D_inverse(l, c) * r[c];
        ex ddq = named_(sum, fmt::format("ab{}_bddq{}", i, l));
        out_.accelerations_of_forces[pj.coordinates[l]] = ddq;
        for (unsigned d = 0; d < 3; ++d) a[d] += J.S(d, l) * ddq;
      }
      acceleration[i] = named_(a, fmt::format("ab{}_ba", i));
    }
  }

  const Model& model_;
  const Mechanics& mechanics_;
  const ParticleTree& tree_;
  std::size_t count_;
  std::vector<Joint> joints_;
  std::vector<matrix> inertia_;     // IA of each particle, summed over its children so far
  std::vector<Vector3> bias_force_;  // pA likewise
  ArticulatedAccelerations out_;
  RecursionQuantities named_{out_.intermediates};
};

}  // namespace

ex applied_generalized_force(const Model& model, const Mechanics& mechanics, std::size_t j) {
  const Symbols& s = model.symbols;
  return mechanics.generalized_force[j] - model.potential.diff(s.coordinates[j]) - mechanics.dissipation.diff(s.velocities[j]);
}

ArticulatedAccelerations articulated_accelerations(const Model& model, const Mechanics& mechanics,
                                                   const ParticleTree& tree) {
  return Recursion(model, mechanics, tree).run();
}

}  // namespace eomgen
