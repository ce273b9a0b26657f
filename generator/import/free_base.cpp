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

std::string unused_joint_name(const std::vector<UrdfJoint>& joints) {
  auto taken = [&](const std::string& name) {
    return std::any_of(joints.begin(), joints.end(), [&](const UrdfJoint& j) { return j.name == name; });
  };
  std::string name = "root";
  for (int k = 2; taken(name); ++k) name = fmt::format("root_{}", k);
  return name;
}

}  // namespace

FreeBase with_free_base(const std::string& urdf) {
  FreeBase out{urdf, "", 0, "", ""};
  std::vector<UrdfJoint> joints = urdf_joints(urdf);
  for (const UrdfJoint& j : joints)
    if (j.type == "floating") {
      out.line = j.line;
      out.problem = fmt::format("joint '{}' already makes the robot's base float", j.name);
      out.hint = "import the robot without --free-base";
      return out;
    }
  std::vector<std::string> roots = root_links(urdf, joints);
  std::size_t robot = element_start(urdf, "robot"), inside = robot == std::string::npos ? robot : past_tag(urdf, robot);
  if (inside == std::string::npos || roots.size() != 1) {
    out.line = robot == std::string::npos ? 1 : line_of(urdf, robot);
    out.problem = roots.empty() ? "the robot has no root link (one link that no joint has as its child) to set free"
                                : fmt::format("the robot has {} root links ('{}' and '{}'{}): which one floats is not clear",
                                              roots.size(), roots[0], roots[1], roots.size() > 2 ? ", …" : "");
    out.hint = "a URDF robot is one tree of links joined by joints, with one root link";
    return out;
  }
  if (roots[0] == "world") {
    auto fixing = std::find_if(joints.begin(), joints.end(), [](const UrdfJoint& j) { return j.parent == "world"; });
    out.line = fixing == joints.end() ? line_of(urdf, robot) : fixing->line;
    out.problem = "the robot's root link is the world itself, to which its joints fix it";
    out.hint = fixing == joints.end() ? "import the robot without --free-base"
                                      : fmt::format("make joint '{}' type=\"floating\" to set its link free, and import "
                                                    "without --free-base", fixing->name);
    return out;
  }
  out.joint = unused_joint_name(joints);
  out.text.insert(inside, fmt::format("<link name=\"world\"/><joint name=\"{}\" type=\"floating\"><parent link=\"world\"/>"
                                      "<child link=\"{}\"/></joint>",
                                      out.joint, roots[0]));
  return out;
}

}  // namespace eomgen
