#include "spatial/joint_velocities.hpp"

#include <algorithm>

#include "model/quaternion.hpp"

namespace eomgen {

using GiNaC::ex;

bool has_spherical_joints(const Model& model) {
  return std::any_of(model.frame_links.begin(), model.frame_links.end(),
                     [](const FrameLink& l) { return l.joint && l.joint->spherical(); });
}

JointVelocities joint_velocities(const Model& model) {
  const Symbols& s = model.symbols;
  std::size_t n = s.num_coordinates();
  JointVelocities v;
  v.coordinate_rates.assign(s.velocities.begin(), s.velocities.end());
  v.of_coordinate.assign(n, -1);
  std::vector<const FrameLink::Joint*> turned_by(n, nullptr);
  for (const FrameLink& l : model.frame_links)
    if (l.joint && l.joint->spherical())
      for (int k : l.joint->quaternion) turned_by[std::size_t(k)] = &*l.joint;
  for (std::size_t j = 0; j < n; ++j) {
    const FrameLink::Joint* ball = turned_by[j];
    if (!ball) {
      v.of_coordinate[j] = int(v.symbols.size());
      v.symbols.push_back(s.velocities[j]);
      v.definitions.push_back({s.velocities[j].get_name(), s.velocities[j]});
      continue;
    }
    if (int(j) != ball->quaternion[0]) continue;
    v.pseudo = true;
    std::array<ex, 4> q, dq;
    for (std::size_t k = 0; k < 4; ++k)
      q[k] = s.coordinates[std::size_t(ball->quaternion[k])], dq[k] = s.velocities[std::size_t(ball->quaternion[k])];
    const std::vector<GiNaC::realsymbol>& w = ball->angular_velocity;
    // q' = ½ q ⊗ (0, ω)
    std::array<ex, 4> rate = quaternion_rates(q, {w[0], w[1], w[2]});
    for (std::size_t k = 0; k < 4; ++k) v.coordinate_rates[std::size_t(ball->quaternion[k])] = rate[k];
    // ω = 2 vec(q* ⊗ q') / |q|²
    ex norm = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    std::array<ex, 3> omega = {2 * (q[0] * dq[1] - q[1] * dq[0] - q[2] * dq[3] + q[3] * dq[2]) / norm,
                               2 * (q[0] * dq[2] - q[2] * dq[0] - q[3] * dq[1] + q[1] * dq[3]) / norm,
                               2 * (q[0] * dq[3] - q[3] * dq[0] - q[1] * dq[2] + q[2] * dq[1]) / norm};
    for (std::size_t k = 0; k < 3; ++k) {
      v.symbols.push_back(w[k]);
      v.definitions.push_back({w[k].get_name(), omega[k]});
    }
  }
  v.rate_matrix.resize(n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t c = 0; c < v.symbols.size(); ++c)
      if (ex w = v.coordinate_rates[j].diff(v.symbols[c]); !w.is_zero()) v.rate_matrix[j].push_back({c, w});
  return v;
}

}  // namespace eomgen
