#include "import/joint_followers.hpp"

#include <set>
#include <utility>

namespace eomgen {

std::vector<JointFollower> joint_followers(const Robot& robot) {
  using Joint = std::pair<int, int>;
  std::set<Joint> following, leading;
  auto type = [&](int body, int joint) {
    return robot.bodies[std::size_t(body)].joints[std::size_t(joint)].type;
  };
  std::vector<JointFollower> out;
  for (std::size_t k = 0; k < robot.couplings.size(); ++k) {
    const RobotCoupling& c = robot.couplings[k];
    if (c.body2 < 0 || c.coefficients[1] == 0 || c.coefficients[2] != 0 || c.coefficients[3] != 0 || c.coefficients[4] != 0)
      continue;
    Joint follower{c.body1, c.joint1}, leader{c.body2, c.joint2};
    auto moves_by_one = [&](const Joint& j) { return type(j.first, j.second) == "hinge" || type(j.first, j.second) == "slide"; };
    if (follower == leader || !moves_by_one(follower) || !moves_by_one(leader)) continue;
    if (following.count(follower) || leading.count(follower) || following.count(leader)) continue;
    following.insert(follower);
    leading.insert(leader);
    double m = c.coefficients[1];
    out.push_back({k, c.body1, c.joint1, c.body2, c.joint2, m, c.reference1 + c.coefficients[0] - m * c.reference2});
  }
  return out;
}

}  // namespace eomgen
