// MuJoCo as an independent oracle for rigid-body trees: the generated rhs of a model and
// MuJoCo's mj_forward on the same robot written as MJCF (tests/crosscheck/mjcf/) give the
// same accelerations at random states and controls, to 1e-12 of their size.
// models/oblique_tree.toml: five joints about oblique axes through offset anchors, a
// prismatic joint, a fixed frame, a placement given as a matrix, full inertia tensors,
// armature, damping, a spring and a geared motor. models/measured_arm.toml: three joints with the
// Panda's first links' layout and measured inertias to 17 digits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "branched_tree.hpp"
#include "measured_arm.hpp"
#include "oblique_tree.hpp"
#include "seven_joint_arm.hpp"

namespace {

struct MujocoModel {
  explicit MujocoModel(const std::string& file) {
    char error[1000] = "";
    model = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
    message = error;
    if (model) data = mj_makeData(model);
  }
  ~MujocoModel() {
    if (data) mj_deleteData(data);
    if (model) mj_deleteModel(model);
  }
  MujocoModel(const MujocoModel&) = delete;
  MujocoModel& operator=(const MujocoModel&) = delete;
  mjModel* model = nullptr;
  mjData* data = nullptr;
  std::string message;
};

std::string mjcf(const std::string& name) { return std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/mjcf/" + name; }

// largest |ours − MuJoCo's| over the largest |qacc|, over `count` random states and controls
template <class Rhs>
double worst_relative_difference(MujocoModel& mj, int n, int m, Rhs rhs, int count) {
  EXPECT_EQ(mj.model->nq, n);
  EXPECT_EQ(mj.model->nu, m);
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0), control(-2.0, 2.0);
  std::vector<double> x(2 * n), xdot(2 * n), u(std::max(m, 1));
  double worst = 0;
  for (int k = 0; k < count; ++k) {
    for (int i = 0; i < n; ++i) mj.data->qpos[i] = x[i] = angle(random), mj.data->qvel[i] = x[n + i] = rate(random);
    for (int i = 0; i < m; ++i) mj.data->ctrl[i] = u[i] = control(random);
    mj_forward(mj.model, mj.data);
    rhs(x.data(), u.data(), xdot.data());
    double size = 0, difference = 0;
    for (int i = 0; i < n; ++i) {
      size = std::max(size, std::abs(mj.data->qacc[i]));
      difference = std::max(difference, std::abs(xdot[n + i] - mj.data->qacc[i]));
      EXPECT_EQ(xdot[i], x[n + i]);
    }
    worst = std::max(worst, difference / size);
  }
  return worst;
}

// the generated model's rhs (with its default parameters) against mj_forward on `file`
template <class Parameters, class Rhs>
void expect_matches_mujoco(const std::string& file, int n, int m, Rhs model_rhs) {
  MujocoModel mj(mjcf(file));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  auto p = Parameters().values();
  auto rhs = [&](const double* x, const double* u, double* xdot) { model_rhs(0.0, x, u, p.data(), xdot); };
  double worst = worst_relative_difference(mj, n, m, rhs, 200);
  std::printf("%s: largest difference from MuJoCo's qacc: %.2g of its size\n", file.c_str(), worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0) << "two independent computations agree to the last bit at every state: suspicious";
}

// a generated model's namespace M: its rhs for double, its sizes and its parameters
#define EXPECT_MATCHES_MUJOCO(M)                                                                            \
  expect_matches_mujoco<eomgen::models::M::Parameters<double>>(#M ".xml", int(eomgen::models::M::num_coordinates), \
                                                               int(eomgen::models::M::num_inputs),                   \
                                                               eomgen::models::M::rhs<double>)

TEST(MujocoOracle, ObliqueJointsThroughOffsetAnchorsMatchMujoco) { EXPECT_MATCHES_MUJOCO(oblique_tree); }

// the robots of tests/crosscheck/models/: a 7-joint arm (a Panda's layout) and a humanoid-like
// tree of 21 hinges about oblique axes through offset anchors, both joint trees
TEST(MujocoOracle, SevenJointArmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(seven_joint_arm); }

TEST(MujocoOracle, BranchedTreeOf21ObliqueHingesMatchesMujoco) { EXPECT_MATCHES_MUJOCO(branched_tree); }

TEST(MujocoOracle, MeasuredArmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(measured_arm); }

}  // namespace
