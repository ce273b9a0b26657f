#include "import/option_forces.hpp"

#include <string>

#include <fmt/format.h>

namespace eomgen {

namespace {

bool switched_off(const mjModel* m, int flag) { return (m->opt.disableflags & flag) != 0; }

// the joints' and fixed tendons' springs and dampers, which MuJoCo's passive force holds with the
// medium's forces; `flags` as the file wrote them
void take_off_passive_forces(bool medium, const std::string& flags, Robot& r) {
  int joints = 0;
  for (RobotBody& body : r.bodies)
    for (RobotJoint& joint : body.joints) {
      joints += joint.damping != 0 || joint.stiffness != 0;
      joint.damping = joint.stiffness = 0;
    }
  if (joints > 0 || !r.tendon_springs.empty() || medium)
    r.notes.push_back(fmt::format("passive forces are switched off in the file (<flag {}/>): the springs and "
                                  "dampers of {} joint(s) and {} tendon(s){} are not carried",
                                  flags, joints, r.tendon_springs.size(), medium ? ", and the medium's forces," : ""));
  r.tendon_springs.clear();
}

// MuJoCo 3.3.6's spring or damper flag alone: the joints' and fixed tendons' springs, or their dampers
void take_off_springs_or_dampers(bool springs, Robot& r) {
  int joints = 0, tendons = 0;
  for (RobotBody& body : r.bodies)
    for (RobotJoint& joint : body.joints) {
      double& value = springs ? joint.stiffness : joint.damping;
      joints += value != 0;
      value = 0;
    }
  for (RobotTendonSpring& tendon : r.tendon_springs) {
    double& value = springs ? tendon.stiffness : tendon.damping;
    tendons += value != 0;
    value = 0;
  }
  if (joints + tendons > 0)
    r.notes.push_back(fmt::format("{0} are switched off in the file (<flag {1}=\"disable\"/>): the {0} of {2} joint(s) and {3} "
                                  "tendon(s) are not carried",
                                  springs ? "springs" : "dampers", springs ? "spring" : "damper", joints, tendons));
}

}  // namespace

void apply_option_forces(const mjModel* m, const PassiveSwitches& passive, Robot& r) {
  if (switched_off(m, mjDSBL_GRAVITY) && r.gravity != Triple{0, 0, 0}) {
    r.gravity = {0, 0, 0};
    r.notes.push_back("gravity is switched off in the file (<flag gravity=\"disable\"/>): the model has none");
  }
  bool medium = m->opt.density > 0 || m->opt.viscosity > 0;
  if (passive.all_off() || switched_off(m, mjDSBL_PASSIVE)) {
    take_off_passive_forces(medium, passive.all_off() ? "spring=\"disable\" damper=\"disable\"" : "passive=\"disable\"", r);
  } else {
    if (passive.springs_off) take_off_springs_or_dampers(true, r);
    if (passive.dampers_off) take_off_springs_or_dampers(false, r);
    if (medium)
      // MuJoCo 2.2's medium acts on each body through the box of its inertia (quadratic drag at the
      // density, Stokes's resistance at the viscosity, relative to the wind)
      r.warnings.push_back({fmt::format("the medium of <option density=\"{:g}\" viscosity=\"{:g}\">: its drag and viscous "
                                        "resistance on every body are not carried",
                                        m->opt.density, m->opt.viscosity),
                            "", "", 0});
  }
  if (switched_off(m, mjDSBL_ACTUATION) && !r.actuators.empty()) {
    r.notes.push_back(fmt::format("actuation is switched off in the file (<flag actuation=\"disable\"/>): its {} actuator(s) "
                                  "are not imported",
                                  r.actuators.size()));
    r.actuators.clear();
  }
  if (switched_off(m, mjDSBL_CLAMPCTRL)) {
    int clamped = 0;
    for (RobotActuator& a : r.actuators) {
      clamped += a.limited;
      a.limited = false;
    }
    if (clamped > 0)
      r.notes.push_back(fmt::format("control clamping is switched off in the file (<flag clampctrl=\"disable\"/>): the controls "
                                    "of {} actuator(s) with a range are not clamped to it",
                                    clamped));
  }
}

}  // namespace eomgen
