/// @file Couplings of two joints that the model writes as one joint following the other's
/// coordinate (model file: `joint = { …, coordinate = "q", multiplier = m, offset = c }`) instead of
/// a holonomic constraint: URDF's mimic and MJCF's equality joint when it is linear. The model then
/// keeps Lagrange II (or Appell's equations) over the tree, with one coordinate fewer and no
/// multiplier: Baxter's two grippers give 17 coordinates instead of 19 and two constraints.
#pragma once

#include <cstddef>
#include <vector>

#include "import/robot.hpp"

namespace eomgen {

/// Joint `joint` of body `body` turns or slides by multiplier·q + offset, q the coordinate of joint
/// `leader_joint` of body `leader_body`, in place of the coupling `coupling` (index into
/// Robot::couplings). The angles are MuJoCo's qpos: q1 − ref1 = c0 + c1 (q2 − ref2) gives
/// multiplier c1 and offset ref1 + c0 − c1 ref2.
struct JointFollower {
  std::size_t coupling;
  int body, joint, leader_body, leader_joint;
  double multiplier, offset;
};

/// The couplings that become followers: linear (c2 = c3 = c4 = 0, c1 ≠ 0) between hinges or slides
/// (a rack and pinion too), a joint's first such coupling where it has several. A chain of them
/// follows the joint at its head, the multipliers and offsets composed; a cycle stays constraints,
/// as do the others. (An actuator on a follower acts on the leader, m times its force.)
std::vector<JointFollower> joint_followers(const Robot& robot);

}  // namespace eomgen
