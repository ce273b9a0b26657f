#include "kinematics/particle_tree.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the indices of the coordinates a position depends on, ascending
std::vector<std::size_t> coordinates_of(const Vector3& r, const Symbols& s) {
  GiNaC::exset used;
  for (const ex& x : r) collect_symbols(x, used);
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < s.coordinates.size(); ++j)
    if (used.count(s.coordinates[j])) out.push_back(j);
  return out;
}

bool depends_on_any(const Vector3& r, const std::vector<GiNaC::realsymbol>& symbols) {
  for (const ex& x : r)
    for (const auto& v : symbols)
      if (x.has(v)) return true;
  return false;
}

std::string model_level_reason(const Model& m) {
  if (m.recursive_kinematics)
    return "its frames are derived link by link (joints, or frames composed in turn), not through the particles' positions";
  if (!m.rigid_bodies.empty()) return "it has rigid bodies; the recursion takes point masses only";
  if (!m.kinetic.is_zero()) return "its [energy] kinetic is not a sum over particles";
  if (!m.constraints.empty()) return "it has constraints";
  if (!m.pseudo_velocities.empty()) return "it has pseudo-velocities";
  if (m.particles.empty()) return "it has no particles";
  for (const Particle& p : m.particles) {
    if (p.position[0].has(m.symbols.time) || p.position[1].has(m.symbols.time) || p.position[2].has(m.symbols.time))
      return fmt::format("particle '{}' moves with t", p.name);
    if (depends_on_any(p.position, m.symbols.inputs)) return fmt::format("particle '{}' moves with an input", p.name);
  }
  return "";
}

}  // namespace

bool ParticleTree::below(std::size_t k, std::size_t i) const {
  for (int at = int(k); at >= 0; at = joints[std::size_t(at)].parent)
    if (std::size_t(at) == i) return true;
  return false;
}

int ParticleTree::coupling(std::size_t i, std::size_t k) const {
  if (below(k, i)) return int(k);
  if (below(i, k)) return int(i);
  return -1;
}

std::vector<std::pair<std::size_t, std::size_t>> ParticleTree::joints_of_coordinates(std::size_t n) const {
  std::vector<std::pair<std::size_t, std::size_t>> of(n);
  for (std::size_t i = 0; i < joints.size(); ++i)
    for (std::size_t b = 0; b < joints[i].coordinates.size(); ++b) of[joints[i].coordinates[b]] = {i, b};
  return of;
}

JointMotion joint_motion(const ParticleJoint& joint, const Symbols& s) {
  JointMotion m;
  Vector3 velocity{0, 0, 0};
  for (std::size_t j : joint.coordinates) {
    Vector3 axis;
    for (unsigned a = 0; a < 3; ++a) {
      axis[a] = joint.displacement[a].diff(s.coordinates[j]);
      velocity[a] += axis[a] * s.velocities[j];
    }
    m.axes.push_back(axis);
  }
  for (unsigned a = 0; a < 3; ++a)
    for (std::size_t j : joint.coordinates) m.bias[a] += velocity[a].diff(s.coordinates[j]) * s.velocities[j];
  return m;
}

ParticleTree find_particle_tree(const Model& model) {
  ParticleTree tree;
  tree.why_not = model_level_reason(model);
  if (!tree.found()) return tree;
  const Symbols& s = model.symbols;
  std::size_t count = model.particles.size();
  std::vector<std::vector<std::size_t>> moved_by(count);
  for (std::size_t i = 0; i < count; ++i) moved_by[i] = coordinates_of(model.particles[i].position, s);
  // a parent moves with a subset of its child's coordinates, so it comes first in this order
  for (std::size_t i = 0; i < count; ++i) tree.order.push_back(i);
  std::stable_sort(tree.order.begin(), tree.order.end(),
                   [&](std::size_t a, std::size_t b) { return moved_by[a].size() < moved_by[b].size(); });
  tree.joints.resize(count);
  std::vector<int> owner(s.coordinates.size(), -1);
  auto fail = [&](std::string why) {
    tree.why_not = std::move(why);
    return tree;
  };
  for (std::size_t at = 0; at < count; ++at) {
    std::size_t i = tree.order[at];
    ParticleJoint& joint = tree.joints[i];
    joint.displacement = model.particles[i].position;
    // the nearest parent: of the earlier particles (fewer or as many coordinates, so the order runs
    // from the most down), the first whose coordinates the displacement leaves out
    for (std::size_t before = at; before-- > 0;) {
      std::size_t p = tree.order[before];
      const auto& cp = moved_by[p];
      if (!std::includes(moved_by[i].begin(), moved_by[i].end(), cp.begin(), cp.end())) continue;
      Vector3 d;
      for (unsigned a = 0; a < 3; ++a) d[a] = (model.particles[i].position[a] - model.particles[p].position[a]).expand();
      std::vector<std::size_t> cd = coordinates_of(d, s), shared;
      std::set_intersection(cd.begin(), cd.end(), cp.begin(), cp.end(), std::back_inserter(shared));
      if (!shared.empty()) continue;
      joint.parent = int(p), joint.displacement = d;
      break;
    }
    joint.coordinates = coordinates_of(joint.displacement, s);
    if (joint.coordinates.size() > 3)
      return fail(fmt::format("particle '{}' hangs from its parent by {} coordinates (at most 3)",
                              model.particles[i].name, joint.coordinates.size()));
    for (std::size_t j : joint.coordinates) {
      if (owner[j] >= 0)
        return fail(fmt::format("coordinate '{}' moves both '{}' and '{}' relative to what they hang from",
                                s.coordinate_names[j], model.particles[std::size_t(owner[j])].name,
                                model.particles[i].name));
      owner[j] = int(i);
    }
  }
  for (std::size_t j = 0; j < owner.size(); ++j)
    if (owner[j] < 0) return fail(fmt::format("coordinate '{}' moves no particle", s.coordinate_names[j]));
  return tree;
}

}  // namespace eomgen
