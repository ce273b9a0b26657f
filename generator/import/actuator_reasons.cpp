#include "import/actuator_reasons.hpp"

#include <fmt/format.h>

#include "import/mujoco_model_parts.hpp"

namespace eomgen {
namespace {

const char* dynamics_name(int type) {
  switch (type) {
    case mjDYN_INTEGRATOR: return "an integrator (da/dt = u)";
    case mjDYN_FILTER: return "a filter (da/dt = (u - a)/tau)";
    case mjDYN_MUSCLE: return "a muscle's";
    default: return "user-defined";
  }
}

const char* transmission_name(int type) {
  switch (type) {
    case mjTRN_SLIDERCRANK: return "a slider-crank";
    case mjTRN_TENDON: return "a spatial tendon (or one through a ball or free joint)";
    case mjTRN_SITE: return "a site";
    case mjTRN_BODY: return "a body's contacts (adhesion)";
    default: return "an unknown transmission";
  }
}

}  // namespace

std::string actuator_left_out_because(const mjModel* m, int a) {
  if (m->actuator_dyntype[a] != mjDYN_NONE)
    return fmt::format("its activation dynamics, {}, add a state of the actuator's own", dynamics_name(m->actuator_dyntype[a]));
  if (m->actuator_gaintype[a] != mjGAIN_FIXED)
    return m->actuator_gaintype[a] == mjGAIN_AFFINE ? "its gain depends on the position and its rate (gaintype affine)"
                                                    : "its gain is a muscle's or user-defined";
  if (m->actuator_biastype[a] != mjBIAS_NONE && m->actuator_biastype[a] != mjBIAS_AFFINE)
    return "its bias is a muscle's or user-defined";
  int type = m->actuator_trntype[a];
  // on a hinge or slide, a joint's axis in its parent's frame is the axis in its own
  if (type == mjTRN_JOINT || type == mjTRN_JOINTINPARENT) {
    if (one_dof_joint(m, m->actuator_trnid[2 * a])) return "";
    return "it drives a ball or free joint";
  }
  if (type == mjTRN_TENDON && fixed_tendon(m, m->actuator_trnid[2 * a])) return "";
  return fmt::format("it acts through {}", transmission_name(type));
}

}  // namespace eomgen
