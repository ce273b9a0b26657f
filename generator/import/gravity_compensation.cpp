#include "import/gravity_compensation.hpp"

#include <cstdlib>

#include <fmt/format.h>

#include "emit/formats.hpp"
#include "import/xml_text.hpp"

namespace eomgen {

bool refuses_gravcomp(const std::string& mujoco_error) {
  return mujoco_error.find("unrecognized attribute: 'gravcomp'") != std::string::npos;
}

void read_gravity_compensations(const std::string& mjcf, std::size_t source, GravityCompensations& out) {
  int ordinal = 0;
  for (std::size_t at = element_start(mjcf, "body"); at != std::string::npos; at = element_start(mjcf, "body", at + 1), ++ordinal) {
    std::size_t end = past_tag(mjcf, at);
    if (end == std::string::npos) break;
    std::optional<std::string> value = attribute(mjcf, at, end, "gravcomp");
    double part = value ? std::strtod(value->c_str(), nullptr) : 0;
    if (part != 0) out.bodies.push_back({attribute(mjcf, at, end, "name").value_or(""), ordinal, source, part});
  }
  if (source == 0) out.body_elements = ordinal;
  else out.includes = true;
}

namespace {

// the body's index in `m`, or −1: by name, or an unnamed one by its place in the only file
int body_of(const mjModel* m, const GravityCompensations& found, const GravityCompensation& c) {
  if (!c.body.empty()) return mj_name2id(m, mjOBJ_BODY, c.body.c_str());
  bool placed = !found.includes && c.source == 0 && found.body_elements == m->nbody - 1;
  return placed ? c.ordinal + 1 : -1;
}

// One part c for every body that moves and has mass (a body welded to the world gives its weight to
// the world): gravity (1 − c) g is the same motion, and cheaper than a force per body, which costs the
// seven-joint arm's rhs 16 % and its jacobian_state 32 % (g++ -O2, one core)
bool one_part_for_all(Robot& r) {
  std::vector<bool> moves(r.bodies.size(), false);
  double part = 0;
  bool found = false;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const RobotBody& body = r.bodies[b];
    moves[b] = !body.joints.empty() || (body.parent >= 0 && moves[std::size_t(body.parent)]);
    if (!moves[b] || body.mass == 0) continue;
    if (found && body.gravity_compensation != part) return false;
    part = body.gravity_compensation, found = true;
  }
  if (!found) return false;
  for (double& g : r.gravity) g *= 1 - part;
  for (RobotBody& body : r.bodies) body.gravity_compensation = 0;
  r.notes.push_back(fmt::format("gravity compensation (MuJoCo 2.3's gravcomp, read from the file's text): every moving body "
                                "takes off {} of its weight, so that gravity is {} of the file's",
                                format_number(part), format_number(1 - part)));
  return true;
}

}  // namespace

void apply_gravity_compensation(const mjModel* m, const GravityCompensations& found, Robot& r) {
  if (found.bodies.empty()) return;
  if (r.gravity == Triple{0, 0, 0} || (m->opt.disableflags & mjDSBL_PASSIVE) != 0) {
    r.notes.push_back(fmt::format("the gravity compensation (gravcomp) of {} body(ies) does nothing here: {}", found.bodies.size(),
                                  r.gravity == Triple{0, 0, 0} ? "there is no gravity" : "the passive forces are switched off"));
    return;
  }
  int carried = 0, lost = 0;
  for (const GravityCompensation& c : found.bodies) {
    int b = body_of(m, found, c);
    if (b < 1 || std::size_t(b) > r.bodies.size()) {
      ++lost;
      continue;
    }
    r.bodies[std::size_t(b - 1)].gravity_compensation = c.part;
    ++carried;
  }
  if (carried > 0 && lost == 0 && one_part_for_all(r)) return;
  if (carried > 0)
    r.notes.push_back(fmt::format("gravity compensation (MuJoCo 2.3's gravcomp, read from the file's text): {} body(ies) carry a "
                                  "force -gravcomp*m*g at their centre of mass",
                                  carried));
  if (lost > 0)
    r.warnings.push_back({fmt::format("the gravity compensation (gravcomp) of {} unnamed body(ies) in an included file, or "
                                      "whose place among the bodies is not plain: not carried (name the bodies)",
                                      lost),
                          "", "", 0});
}

}  // namespace eomgen
