#include "kinematics/drawn_bodies.hpp"

#include "kinematics/particle_tree.hpp"

namespace eomgen {

std::vector<DrawnBody> drawn_bodies(const Model& model) {
  std::vector<DrawnBody> drawing = model.drawing;
  std::vector<int> drawn_particle;
  for (std::size_t i = 0; i < drawing.size(); ++i)
    if (drawing[i].kind == DrawnBody::Kind::particle) drawn_particle.push_back(int(i));
  if (drawn_particle.size() != model.particles.size() || model.particles.empty()) return drawing;
  ParticleTree tree = find_particle_tree(model);
  if (!tree.found()) return drawing;
  for (std::size_t p = 0; p < model.particles.size(); ++p) {
    DrawnBody& d = drawing[std::size_t(drawn_particle[p])];
    int parent = tree.joints[p].parent;
    if (d.parent < 0 && parent >= 0) d.parent = drawn_particle[std::size_t(parent)];
  }
  return drawing;
}

void remove_drawn_bodies(std::vector<DrawnBody>& drawing, const std::function<bool(const DrawnBody&)>& gone) {
  std::vector<int> index(drawing.size(), -1);
  std::vector<DrawnBody> kept;
  for (std::size_t i = 0; i < drawing.size(); ++i)
    if (!gone(drawing[i])) index[i] = int(kept.size()), kept.push_back(drawing[i]);
  for (DrawnBody& d : kept)
    if (d.parent >= 0) d.parent = index[std::size_t(d.parent)];
  drawing = std::move(kept);
}

}  // namespace eomgen
