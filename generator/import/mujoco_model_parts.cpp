#include "import/mujoco_model_parts.hpp"

#include <fmt/format.h>

namespace eomgen {

std::string name_of(const mjModel* m, const int* addresses, int i) {
  return addresses ? std::string(m->names + addresses[i]) : std::string();
}

bool one_dof_joint(const mjModel* m, int j) { return j >= 0 && (m->jnt_type[j] == mjJNT_HINGE || m->jnt_type[j] == mjJNT_SLIDE); }

void place_joint(const mjModel* m, int j, int& body, int& joint, double& reference) {
  body = m->jnt_bodyid[j] - 1;
  joint = j - m->body_jntadr[body + 1];
  reference = m->qpos0[m->jnt_qposadr[j]];
}

std::optional<std::vector<TendonJoint>> fixed_tendon(const mjModel* m, int t) {
  std::vector<TendonJoint> joints;
  for (int w = m->tendon_adr[t]; w < m->tendon_adr[t] + m->tendon_num[t]; ++w) {
    if (m->wrap_type[w] != mjWRAP_JOINT || !one_dof_joint(m, m->wrap_objid[w])) return std::nullopt;
    TendonJoint joint;
    double reference = 0;
    place_joint(m, m->wrap_objid[w], joint.body, joint.joint, reference);
    joint.coefficient = m->wrap_prm[w];
    joints.push_back(joint);
  }
  if (joints.empty()) return std::nullopt;
  return joints;
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size() && k < 4; ++k) text += (k ? ", '" : "'") + names[k] + "'";
  if (names.size() > 4) text += fmt::format(" and {} more", names.size() - 4);
  return text;
}

}  // namespace eomgen
