/// @file M and the inertia terms of f for a tree of particles in few terms: with S_j the axis of
/// coordinate j (kinematics/particle_tree.hpp) and c_l the bias acceleration of joint l,
///   M_jl = m̄ S_j · S_l,   f_j (inertia) = −S_j · Σ_l m̄ c_l,
/// m̄ the mass of the deeper of the two joints' subtrees (the joints on one branch only), held
/// as one symbol per subtree. The sums over the particles, Σ_k m_k J_kj · J_kl and
/// Σ_k m_k J_kj · a_k, have O(n) and O(n²) terms per entry on a chain: simplifying them was most
/// of a long chain's derivation. Replacing the symbols by their sums after the simplification
/// gives the same expanded polynomial, whose collection is then the same equations.
#pragma once

#include <vector>

#include "kinematics/particle_tree.hpp"

namespace eomgen {

struct ParticleTreeTerms {
  GiNaC::matrix mass_matrix;               // in the subtree masses
  std::vector<GiNaC::ex> inertia_forces;   // f without applied forces, potential and dissipation
  GiNaC::exmap subtree_masses;             // each subtree mass symbol → the sum of its particles' masses
};

ParticleTreeTerms particle_tree_terms(const Model& model, const ParticleTree& tree);

}  // namespace eomgen
