#include "import/free_base.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "import/urdf_text.hpp"
#include "import/xml_text.hpp"

namespace eomgen {

namespace {

// the links that are no joint's child, in the file's order
std::vector<std::string> root_links(const std::string& urdf, const std::vector<UrdfJoint>& joints) {
  std::set<std::string> children;
  for (const UrdfJoint& j : joints) children.insert(j.child);
  std::vector<std::string> roots;
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1))
    if (auto name = attribute(urdf, at, urdf.find('>', at), "name"); name && !children.count(*name)) roots.push_back(*name);
  return roots;
}

// the line of the <link> named `name`, 1 when there is none
int link_line(const std::string& urdf, const std::string& name) {
  for (std::size_t at = element_start(urdf, "link"); at != std::string::npos; at = element_start(urdf, "link", at + 1))
    if (attribute(urdf, at, urdf.find('>', at), "name") == name) return line_of(urdf, at);
  return 1;
}

// `root`, or `root_2`, `root_3`, … when a joint has that name
template <class Taken>
std::string root_joint_name(const Taken& taken) {
  std::string name = "root";
  for (int k = 2; taken(name); ++k) name = fmt::format("root_{}", k);
  return name;
}

std::string unused_joint_name(const std::vector<UrdfJoint>& joints) {
  return root_joint_name([&](const std::string& name) {
    return std::any_of(joints.begin(), joints.end(), [&](const UrdfJoint& j) { return j.name == name; });
  });
}

// "'a' and 'b'", with ", …" when there are more
std::string listed_pair(const std::string& first, const std::string& second, std::size_t count) {
  return fmt::format("'{}' and '{}'{}", first, second, count > 2 ? ", …" : "");
}

// A robot whose root link is the world (a UR arm's world -> base_link): the one fixed joint that
// holds it to the world floats instead, so that its child floats from where the joint held it; a
// world holding two links, or holding its link by a joint that moves, leaves no base that is
// plainly the one to set free.
FreeBase mounted_on_the_world(const std::string& urdf, const std::vector<UrdfJoint>& joints, std::size_t robot) {
  FreeBase out;
  std::vector<const UrdfJoint*> held;
  for (const UrdfJoint& j : joints)
    if (j.parent == "world") held.push_back(&j);
  if (held.size() != 1 || held[0]->type != "fixed") {
    out.line = held.empty() ? line_of(urdf, robot) : held[0]->line;
    out.problem = held.size() > 1 ? fmt::format("the robot's root link is the world itself, which holds {} links ({}): "
                                                "which one floats is not clear",
                                                held.size(), listed_pair(held[0]->child, held[1]->child, held.size()))
                                  : "the robot's root link is the world itself, to which its joints fix it";
    out.hint = held.size() == 1 ? fmt::format("make joint '{}' type=\"floating\" to set its link free, and import "
                                              "without --free-base", held[0]->name)
                                : "make the joint of the link that floats type=\"floating\", and import without --free-base";
    return out;
  }
  out.link = held[0]->child;
  out.joint = held[0]->name;
  out.note = fmt::format("--free-base: joint '{}', which fixed link '{}' to the world, is floating instead", held[0]->name,
                         held[0]->child);
  return out;
}

// the line of the MJCF <body> named `name`, 1 when the file does not write it (an included file's)
int body_line(const std::string& mjcf, const std::string& name) {
  for (std::size_t at = element_start(mjcf, "body"); at != std::string::npos; at = element_start(mjcf, "body", at + 1))
    if (attribute(mjcf, at, mjcf.find('>', at), "name") == name) return line_of(mjcf, at);
  return 1;
}

// whether a body below `top` (MuJoCo's bodies come parents first) has a joint
bool carries_joints(const Robot& r, std::size_t top) {
  std::vector<bool> below(r.bodies.size(), false);
  below[top] = true;
  for (std::size_t b = top + 1; b < r.bodies.size(); ++b) {
    int parent = r.bodies[b].parent;
    below[b] = parent >= 0 && below[std::size_t(parent)];
    if (below[b] && !r.bodies[b].joints.empty()) return true;
  }
  return false;
}

std::string unused_joint_name(const Robot& r) {
  return root_joint_name([&](const std::string& name) {
    return std::any_of(r.bodies.begin(), r.bodies.end(), [&](const RobotBody& b) {
      return std::any_of(b.joints.begin(), b.joints.end(), [&](const RobotJoint& j) { return j.name == name; });
    });
  });
}

}  // namespace

FreeBase free_base_of_mjcf(const Robot& r, const std::string& mjcf) {
  FreeBase out;
  std::vector<std::size_t> bases, held;
  std::vector<std::string> base_names;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const RobotBody& body = r.bodies[b];
    if (body.parent >= 0) continue;
    for (const RobotJoint& j : body.joints)
      if (j.type == "free") {
        out.line = body_line(mjcf, body.name);
        out.problem = fmt::format("body '{}' floats already, by its free joint '{}'", body.name, j.name);
        out.hint = "import the robot without --free-base";
        return out;
      }
    if (!body.joints.empty()) held.push_back(b);
    else if (carries_joints(r, b)) bases.push_back(b), base_names.push_back(body.name);
  }
  // a single rigid body: the one body there, without joints
  if (bases.empty() && held.empty())
    for (std::size_t b = 0; b < r.bodies.size(); ++b)
      if (r.bodies[b].parent < 0) bases.push_back(b), base_names.push_back(r.bodies[b].name);
  if (bases.size() == 1) {
    out.link = r.bodies[bases[0]].name;
    out.link_line = body_line(mjcf, out.link);
    out.joint = unused_joint_name(r);
    return out;
  }
  if (bases.size() > 1) {
    out.line = body_line(mjcf, base_names[0]);
    out.problem = fmt::format("{} bodies in <worldbody> carry joints without having one ({}): which one floats is not clear",
                              bases.size(), listed_pair(base_names[0], base_names[1], base_names.size()));
    out.hint = "put <freejoint/> in the body that floats, and import without --free-base";
  } else if (!held.empty()) {
    const RobotBody& body = r.bodies[held[0]];
    out.line = body_line(mjcf, body.name);
    out.problem = fmt::format("body '{}' at the top of the robot is held to the world by its {} '{}', and no body without "
                              "joints carries the robot to be set free",
                              body.name, body.joints[0].type, body.joints[0].name);
    out.hint = fmt::format("put the robot in a <body> without joints (its base) to set that free, or give '{}' a "
                           "<freejoint/> in place of its joints and import without --free-base",
                           body.name);
  } else {
    out.line = 1;
    out.problem = "the model has no body in <worldbody> to set free";
    out.hint = "an MJCF robot's bodies go in <worldbody>";
  }
  return out;
}

FreeBase free_base_of(const std::string& urdf) {
  FreeBase out;
  std::vector<UrdfJoint> joints = urdf_joints(urdf);
  for (const UrdfJoint& j : joints)
    if (j.type == "floating") {
      out.line = j.line;
      out.problem = fmt::format("joint '{}' already makes the robot's base float", j.name);
      out.hint = "import the robot without --free-base";
      return out;
    }
  std::vector<std::string> roots = root_links(urdf, joints);
  std::size_t robot = element_start(urdf, "robot");
  if (robot == std::string::npos || roots.size() != 1) {
    out.line = robot == std::string::npos ? 1 : line_of(urdf, robot);
    out.problem = roots.empty() ? "the robot has no root link (one link that no joint has as its child) to set free"
                                : fmt::format("the robot has {} root links ({}): which one floats is not clear",
                                              roots.size(), listed_pair(roots[0], roots[1], roots.size()));
    out.hint = "a URDF robot is one tree of links joined by joints, with one root link";
    return out;
  }
  if (roots[0] == "world") {
    FreeBase mounted = mounted_on_the_world(urdf, joints, robot);
    mounted.link_line = link_line(urdf, mounted.link);
    return mounted;
  }
  out.link = roots[0];
  out.link_line = link_line(urdf, roots[0]);
  out.joint = unused_joint_name(joints);
  return out;
}

bool set_free(Robot& r, const FreeBase& freed) {
  auto floating = std::find_if(r.bodies.begin(), r.bodies.end(),
                               [&](const RobotBody& b) { return b.name == freed.link && b.parent < 0; });
  if (floating == r.bodies.end()) return false;
  RobotJoint joint;
  joint.name = freed.joint;
  joint.type = "free";
  joint.initial_position = {floating->position[0],    floating->position[1],    floating->position[2],
                            floating->orientation[0], floating->orientation[1], floating->orientation[2],
                            floating->orientation[3]};
  joint.initial_velocity.assign(6, 0.0);
  floating->joints.insert(floating->joints.begin(), joint);
  return true;
}

std::optional<std::string> massless_free_base(const Robot& r, const FreeBase& freed) {
  // the floating link and the links fixed to it, found in one pass: MuJoCo's bodies come parents first
  std::vector<bool> rigid(r.bodies.size(), false);
  double mass = 0, moments = 0;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const RobotBody& body = r.bodies[b];
    bool top = body.name == freed.link && body.parent < 0;
    rigid[b] = top || (body.parent >= 0 && rigid[std::size_t(body.parent)] && body.joints.empty());
    if (rigid[b]) mass += body.mass, moments += body.principal_inertia[0] + body.principal_inertia[1] + body.principal_inertia[2];
  }
  if (mass > 0 || moments > 0) return std::nullopt;
  std::vector<const RobotBody*> carried;
  for (const RobotBody& body : r.bodies)
    if (body.parent >= 0 && rigid[std::size_t(body.parent)] && !body.joints.empty()) carried.push_back(&body);
  if (carried.size() != 1) return std::nullopt;
  const RobotJoint& joint = carried[0]->joints[0];
  return fmt::format("link '{}' set free has no mass and no moment of inertia and carries one link, '{}': the free joint's "
                     "motion along joint '{}' moves nothing, so that M is singular",
                     freed.link, carried[0]->name, joint.name);
}

}  // namespace eomgen
