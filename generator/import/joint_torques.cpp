#include "import/joint_torques.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "import/urdf_text.hpp"

namespace eomgen {

void add_joint_torques(const std::string& urdf, Robot& r) {
  std::vector<std::string> followers;
  for (const UrdfMimic& mimic : urdf.empty() ? std::vector<UrdfMimic>{} : urdf_mimics(urdf)) followers.push_back(mimic.joint);
  std::vector<UrdfJoint> stated = urdf.empty() ? std::vector<UrdfJoint>{} : urdf_joints(urdf);
  auto effort = [&](const std::string& name) {
    auto found = std::find_if(stated.begin(), stated.end(), [&](const UrdfJoint& j) { return j.name == name; });
    return found == stated.end() ? std::nullopt : found->effort;
  };
  for (std::size_t b = 0; b < r.bodies.size(); ++b)
    for (std::size_t k = 0; k < r.bodies[b].joints.size(); ++k) {
      const RobotJoint& j = r.bodies[b].joints[k];
      if ((j.type != "hinge" && j.type != "slide") ||
          std::find(followers.begin(), followers.end(), j.name) != followers.end())
        continue;
      RobotActuator a;
      a.name = "tau_" + (j.name.empty() ? fmt::format("{}_{}", r.bodies[b].name, k + 1) : j.name);
      a.body = int(b), a.joint = int(k);
      if (std::optional<double> limit = effort(j.name))
        a.remark = fmt::format("effort limit {} in the file: not enforced", *limit);
      r.actuators.push_back(a);
    }
}

}  // namespace eomgen
