#include "import/joint_followers.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace eomgen {

std::vector<JointFollower> joint_followers(const Robot& robot) {
  using Joint = std::pair<int, int>;
  auto moves_by_one = [&](const Joint& j) {
    const std::string& type = robot.bodies[std::size_t(j.first)].joints[std::size_t(j.second)].type;
    return type == "hinge" || type == "slide";
  };
  // each joint's coupling to the joint it follows, θ = m θ_leader + o (the first, where a joint has several)
  struct Link {
    std::size_t coupling;
    Joint leader;
    double multiplier, offset;
  };
  std::map<Joint, Link> follows;
  for (std::size_t k = 0; k < robot.couplings.size(); ++k) {
    const RobotCoupling& c = robot.couplings[k];
    if (c.body2 < 0 || c.coefficients[1] == 0 || c.coefficients[2] != 0 || c.coefficients[3] != 0 || c.coefficients[4] != 0)
      continue;
    Joint follower{c.body1, c.joint1}, leader{c.body2, c.joint2};
    if (follower == leader || !moves_by_one(follower) || !moves_by_one(leader) || follows.count(follower)) continue;
    double m = c.coefficients[1];
    follows[follower] = {k, leader, m, c.reference1 + c.coefficients[0] - m * c.reference2};
  }
  // a chain of them composed down to the joint at its head, θ = m (m' θ'' + o') + o; a cycle has no
  // head, and its couplings stay constraints
  std::vector<JointFollower> out;
  for (const auto& [follower, link] : follows) {
    Link head = link;
    std::size_t steps = 0;
    for (auto up = follows.find(head.leader); up != follows.end() && steps <= follows.size(); up = follows.find(head.leader), ++steps)
      head = {head.coupling, up->second.leader, head.multiplier * up->second.multiplier,
              head.multiplier * up->second.offset + head.offset};
    if (steps > follows.size()) continue;
    out.push_back({link.coupling, follower.first, follower.second, head.leader.first, head.leader.second, head.multiplier, head.offset});
  }
  // in the couplings' order, as the file gives them
  std::sort(out.begin(), out.end(), [](const JointFollower& a, const JointFollower& b) { return a.coupling < b.coupling; });
  return out;
}

}  // namespace eomgen
