#include "import/mjcf_actuators.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "import/actuator_reasons.hpp"
#include "import/inherited_ranges.hpp"
#include "import/mjcf_reader.hpp"
#include "import/mujoco_model_parts.hpp"
#include "import/servo_damping.hpp"

namespace eomgen {
namespace {

// MuJoCo 3's position servo with kv or dampratio, read as its user value (servo_damping.hpp): bias [0, −kp, 0] as
// MuJoCo 2.2.2 sets it, and the velocity's −kv
bool position_servo(const mjModel* m, int a) {
  const double* bias = m->actuator_biasprm + mjNBIAS * a;
  return position_like(m, a) && bias[0] == 0 && bias[2] == 0;
}

// MuJoCo 3's inheritrange, read as the group (inherited_ranges.hpp): the control range from the
// joint's or tendon's
void inherit_control_range(const mjModel* m, int a, RobotActuator& act, Robot& r) {
  std::string why_not;
  if (auto inherited = inherited_control_range(m, a, why_not)) act.limited = true, act.range = *inherited;
  else if (!why_not.empty())
    r.warnings.push_back({fmt::format("actuator '{}': inheritrange: {}", act.name, why_not), "actuator",
                          name_of(m, m->name_actuatoradr, a), a + 1});
}

// actuator a's drive, gear, ranges and affine bias as MuJoCo 2.2.2 compiled them
RobotActuator plain_actuator(const mjModel* m, int a, const std::string& name) {
  RobotActuator act;
  act.name = name;
  int j = m->actuator_trnid[2 * a];
  double reference = 0;
  if (m->actuator_trntype[a] == mjTRN_TENDON) act.tendon = *fixed_tendon(m, j);
  else place_joint(m, j, act.body, act.joint, reference);
  act.gain = m->actuator_gainprm[mjNGAIN * a] * m->actuator_gear[6 * a];
  act.limited = m->actuator_ctrllimited[a];
  act.range = {m->actuator_ctrlrange[2 * a], m->actuator_ctrlrange[2 * a + 1]};
  act.gear = m->actuator_gear[6 * a];
  if (m->actuator_biastype[a] == mjBIAS_AFFINE)
    act.bias = {m->actuator_biasprm[mjNBIAS * a], m->actuator_biasprm[mjNBIAS * a + 1], m->actuator_biasprm[mjNBIAS * a + 2]};
  act.force_limited = m->actuator_forcelimited[a];
  act.force_range = {m->actuator_forcerange[2 * a], m->actuator_forcerange[2 * a + 1]};
  return act;
}

}  // namespace

void read_actuators(const mjModel* m, const LeftOut& left_out, Robot& r) {
  // at qpos0, for a servo's damping ratio (servo_damping.hpp)
  bool ratio_in_bias = false;
  for (int a = 0; a < m->nu; ++a) ratio_in_bias = ratio_in_bias || reads_bias_as_damping_ratio(m, a);
  std::unique_ptr<mjData, void (*)(mjData*)> initial(left_out.servo_damping_as_user || ratio_in_bias ? mj_makeData(m) : nullptr,
                                                     mj_deleteData);
  if (initial) mj_fwdPosition(m, initial.get());
  std::vector<std::string> ratios;  // the carried actuators whose biasprm[2] MuJoCo 3 reads as a damping ratio
  for (int a = 0; a < m->nu; ++a) {
    std::string name = name_of(m, m->name_actuatoradr, a);
    if (name.empty()) name = fmt::format("actuator{}", a);
    if (std::string why = actuator_left_out_because(m, a); !why.empty()) {
      r.warnings.push_back({fmt::format("actuator '{}' is left out: {}; eomgen carries motors and servos (a force affine in "
                                        "the control, the position and its rate) on a hinge, a slide or a fixed tendon of them",
                                        name, why),
                            "actuator", name_of(m, m->name_actuatoradr, a), a + 1});
      continue;
    }
    RobotActuator act = plain_actuator(m, a, name);
    if (left_out.servo_damping_as_user && m->nuser_actuator > 0 && position_servo(m, a))
      act.bias[2] = -servo_velocity_gain(m, initial.get(), a, m->actuator_user[m->nuser_actuator * a]);
    if (reads_bias_as_damping_ratio(m, a))
      act.bias[2] = -servo_velocity_gain(m, initial.get(), a, -act.bias[2]), ratios.push_back(name);
    if (left_out.inheritrange_as_group && position_servo(m, a)) inherit_control_range(m, a, act, r);
    r.actuators.push_back(act);
  }
  if (!ratios.empty())
    r.notes.push_back(fmt::format("{} actuator(s) of a position servo's shape with a positive velocity coefficient ({}) read as "
                                  "MuJoCo 3 reads them: that coefficient is the damping ratio ζ of kv = 2 ζ sqrt(kp m), m the "
                                  "inertia the servo sees at qpos0 (MuJoCo {} would feed the motion)",
                                  ratios.size(), listed(ratios), mj_version_text()));
}

}  // namespace eomgen
