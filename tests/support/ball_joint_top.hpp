/// @file models/ball_joint_top.toml's numbers, written out for the tests that check its equilibria:
/// the centre from the anchor in the body's axes, and the inertia about the pivot (m = 1.5).
#pragma once

#include <Eigen/Dense>

namespace eomgen::test {

inline Eigen::Vector3d top_centre_from_anchor() { return {0.12 - 0.1, 0.03, 0.25}; }

inline Eigen::Matrix3d top_inertia_about_pivot() {
  Eigen::Matrix3d I;
  I << 0.02, 0.001, -0.002, 0.001, 0.025, 0.0015, -0.002, 0.0015, 0.04;
  Eigen::Vector3d r = top_centre_from_anchor();
  return I + 1.5 * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

}  // namespace eomgen::test
