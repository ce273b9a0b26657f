// The tree benchmark's hand-written peer, Featherstone's articulated-body algorithm over Eigen
// (tests/benchmarks/articulated_body.hpp), against MuJoCo's mj_forward: before its time is set
// beside the generated rhs, its accelerations must be MuJoCo's on the benchmark's robots and on
// ball and free joints, at random states and controls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../benchmarks/articulated_body.hpp"
#include "mujoco_model.hpp"

namespace {

// largest |ABA − MuJoCo| of qacc over the largest |qacc|, over `count` random states and controls
template <class Scalar>
double worst_relative_difference(const std::string& file, int count) {
  MujocoModel mj(mjcf(file));
  EXPECT_NE(mj.model, nullptr) << mj.message;
  if (!mj.model) return 1;
  mj.model->opt.disableflags |= mjDSBL_LIMIT | mjDSBL_CONTACT;
  featherstone::ArticulatedBody<Scalar> aba(mj.model);
  std::mt19937 random(27);
  std::uniform_real_distribution<double> control(-2.0, 2.0);
  std::vector<Scalar> qacc(std::size_t(mj.model->nv));
  double worst = 0;
  for (int k = 0; k < count; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    for (int i = 0; i < mj.model->nu; ++i) mj.data->ctrl[i] = control(random);
    mj_forward(mj.model, mj.data);
    aba.accelerations(mj.data->qpos, mj.data->qvel, mj.data->qfrc_actuator, qacc.data());
    double size = 0, difference = 0;
    for (int i = 0; i < mj.model->nv; ++i) {
      size = std::max(size, std::abs(mj.data->qacc[i]));
      difference = std::max(difference, double(std::abs(qacc[std::size_t(i)] - Scalar(mj.data->qacc[i]))));
    }
    worst = std::max(worst, difference / size);
  }
  std::printf("%s, %s: largest difference from MuJoCo's qacc: %.2g of its size\n", file.c_str(),
              sizeof(Scalar) == sizeof(double) ? "double" : "long double", worst);
  return worst;
}

// the robots it is timed on, in double as the benchmark runs it
TEST(ArticulatedBodyPeer, MatchesMujocoOnTheBenchmarkRobots) {
  for (const char* robot : {"measured_arm.xml", "oblique_tree.xml", "seven_joint_arm.xml", "branched_tree.xml", "quadruped.xml"}) {
    double worst = worst_relative_difference<double>(robot, 100);
    EXPECT_LT(worst, 1e-12) << robot;
    EXPECT_GT(worst, 0.0) << robot << ": agrees with MuJoCo to the last bit at every state: suspicious";
  }
}

// ball and free joints, two joints in one body, springs, references (MuJoCo's ref), geared motors.
// In long double: on ball_chain, whose slide carries the lower links up to 3 m away, the double
// recursion loses two more digits than MuJoCo's (1.8e-11; the generated rhs 2.2e-13); in long
// double what is left is MuJoCo's own rounding
TEST(ArticulatedBodyPeer, MatchesMujocoOnBallFreeAndStackedJoints) {
  for (const char* robot : {"ball_chain.xml", "tumbling_body.xml", "mjcf_features.xml"})
    EXPECT_LT(worst_relative_difference<long double>(robot, 100), 1e-12) << robot;
}

}  // namespace
