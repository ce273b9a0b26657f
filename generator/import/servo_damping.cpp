#include "import/servo_damping.hpp"

#include <cmath>

#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_position_damping(const std::string& mujoco_error) {
  return (mujoco_error.find("unrecognized attribute: 'kv'") != std::string::npos ||
          mujoco_error.find("unrecognized attribute: 'dampratio'") != std::string::npos) &&
         mujoco_error.find("Element 'position'") != std::string::npos;
}

bool has_actuator_user_values(const std::string& mjcf) {
  return any_tag_sets(mjcf, mjcf_actuator_elements(), "user");
}

std::optional<std::string> with_servo_damping_as_user(const std::string& mjcf) {
  std::string out = with_attribute_renamed(mjcf, "position", "kv", "user");
  for (std::size_t at = element_start(out, "position"); at != std::string::npos; at = element_start(out, "position", at + 1)) {
    std::size_t end = past_tag(out, at);
    if (end == std::string::npos) break;
    auto span = attribute_span(out, at, end, "dampratio");
    if (!span) continue;
    std::size_t open = out.find_first_of("\"'", span->first), first = out.find_first_not_of(" \t\r\n", open + 1);
    if (out[first] == '-') return std::nullopt;
    out.insert(first, "-");
    out.replace(span->first, 9, "user");
  }
  return out;
}

bool position_like(const mjModel* m, int a) {
  return m->actuator_biastype[a] == mjBIAS_AFFINE && m->actuator_gainprm[mjNGAIN * a] == -m->actuator_biasprm[mjNBIAS * a + 1];
}

bool reads_bias_as_damping_ratio(const mjModel* m, int a) { return position_like(m, a) && m->actuator_biasprm[mjNBIAS * a + 2] > 0; }

double servo_velocity_gain(const mjModel* m, const mjData* d, int a, double damping) {
  if (!(damping < 0)) return damping;
  // the inertia reflected through the transmission: Σ M_ii / moment_i² over the velocities it moves
  double mass = 0;
  for (int i = 0; i < m->nv; ++i) {
    double moment = d->actuator_moment[a * m->nv + i];
    if (moment * moment > mjMINVAL) mass += d->qM[m->dof_Madr[i]] / (moment * moment);
  }
  return -damping * 2 * std::sqrt(m->actuator_gainprm[mjNGAIN * a] * mass);
}

}  // namespace eomgen
