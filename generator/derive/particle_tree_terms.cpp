#include "derive/particle_tree_terms.hpp"

#include <fmt/format.h>

#include "kinematics/vector3.hpp"

namespace eomgen {

using GiNaC::ex;

ParticleTreeTerms particle_tree_terms(const Model& model, const ParticleTree& tree) {
  const Symbols& s = model.symbols;
  std::size_t count = model.particles.size(), n = s.num_coordinates();
  ParticleTreeTerms out;
  // m̄_i = m_i + Σ m̄_child as sums of the particles' masses, leaves first; one symbol each
  std::vector<ex> sums(count), masses(count);
  for (std::size_t i = 0; i < count; ++i) sums[i] = model.particles[i].mass;
  for (std::size_t at = count; at-- > 0;) {
    std::size_t i = tree.order[at];
    if (int parent = tree.joints[i].parent; parent >= 0) sums[std::size_t(parent)] += sums[i];
  }
  for (std::size_t i = 0; i < count; ++i) {
    GiNaC::symbol mass(fmt::format("subtree_mass_{}", i));
    masses[i] = mass;
    out.subtree_masses[mass] = sums[i];
  }
  std::vector<JointMotion> motion;
  for (std::size_t i = 0; i < count; ++i) motion.push_back(joint_motion(tree.joints[i], s));
  std::vector<std::pair<std::size_t, std::size_t>> joint_of = tree.joints_of_coordinates(n);
  auto coupling = [&](std::size_t i, std::size_t k) -> ex {
    int by = tree.coupling(i, k);
    return by < 0 ? ex(0) : masses[std::size_t(by)];
  };
  // Σ_{k ∈ subtree(i)} m_k a_k at q'' = 0 (a_k = Σ of c over the joints from the root to k), once per
  // particle that has coordinates
  std::vector<Vector3> force(count, Vector3{0, 0, 0});
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < count && !tree.joints[i].coordinates.empty(); ++k)
      force[i] = force[i] + scaled(coupling(i, k), motion[k].bias);
  out.mass_matrix = GiNaC::matrix(unsigned(n), unsigned(n));
  for (std::size_t j = 0; j < n; ++j) {
    auto [i, b] = joint_of[j];
    const Vector3& S = motion[i].axes[b];
    for (std::size_t l = j; l < n; ++l) {
      auto [k, c] = joint_of[l];
      out.mass_matrix(unsigned(j), unsigned(l)) = coupling(i, k) * dot(S, motion[k].axes[c]);
      out.mass_matrix(unsigned(l), unsigned(j)) = out.mass_matrix(unsigned(j), unsigned(l));
    }
    out.inertia_forces.push_back(-dot(S, force[i]));
  }
  return out;
}

}  // namespace eomgen
