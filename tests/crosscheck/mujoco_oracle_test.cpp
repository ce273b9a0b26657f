// MuJoCo as an independent oracle for rigid-body trees: the generated rhs of a model and
// MuJoCo's mj_forward on the same robot written as MJCF (tests/crosscheck/mjcf/) give the
// same accelerations at random states and controls, to 1e-12 of their size, mass_matrix and
// forcing are MuJoCo's M and forces, and jacobian_state agrees with central differences of
// MuJoCo's accelerations.
// models/oblique_tree.toml: five joints about oblique axes through offset anchors, a
// prismatic joint, a fixed frame, a placement given as a matrix, full inertia tensors,
// armature, damping, a spring and a geared motor. models/measured_arm.toml: three joints with the
// Panda's first links' layout and measured inertias to 17 digits. A quadruped on a floating base
// and a free body: ball and free joints in MuJoCo's qpos and qvel layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mujoco_model.hpp"
#include "support/urdf_inertias.hpp"

#include "branched_tree.hpp"
#include "floating_humanoid.hpp"
#include "floating_snake.hpp"
#include "geared_gripper.hpp"
#include "hinge_chain.hpp"
#include "humanoid_beside_a_free_body.hpp"
#include "measured_arm.hpp"
#include "oblique_tree.hpp"
#include "quadruped.hpp"
#include "seven_joint_arm.hpp"
#include "tumbling_body.hpp"

#include "ball_chain_imported.hpp"
#include "ball_ragdoll_imported.hpp"
#include "evenly_compensated_arm_imported.hpp"
#include "gravity_compensated_arm_imported.hpp"
#include "joint_force_ranges_imported.hpp"
#include "measured_arm_imported.hpp"
#include "mjcf_features_imported.hpp"
#include "oblique_tree_imported.hpp"
#include "quadruped_imported.hpp"
#include "ragdoll_beside_free_objects_imported.hpp"
#include "servo_arm_imported.hpp"
#include "snake_beside_free_objects_imported.hpp"
#include "switched_off_forces_imported.hpp"
#include "tendon_gripper_imported.hpp"
#include "seven_joint_arm_imported.hpp"
#include "tumbling_body_imported.hpp"
#include "seven_joint_arm_from_urdf.hpp"
#include "two_link_arm_from_urdf.hpp"
#include "two_axis_shoulder_from_urdf.hpp"

namespace {

// q' of the state by MuJoCo's own integration of the positions (mj_integratePos, which turns a
// quaternion by exp(ω dt) about the body's axes), as a central difference: to about 1e-10
std::vector<double> coordinate_rates(const mjModel* m, const double* qpos, const double* qvel) {
  const double h = 1e-6;
  std::vector<double> ahead(qpos, qpos + m->nq), behind(ahead), rates(ahead.size());
  mj_integratePos(m, ahead.data(), qvel, h);
  mj_integratePos(m, behind.data(), qvel, -h);
  for (std::size_t i = 0; i < rates.size(); ++i) rates[i] = (ahead[i] - behind[i]) / (2 * h);
  return rates;
}

// largest |ours − MuJoCo's| over the largest |qacc|, over `count` random states and controls
template <class Rhs>
double worst_relative_difference(MujocoModel& mj, int nq, int nv, int m, Rhs rhs, int count) {
  EXPECT_EQ(mj.model->nq, nq);
  EXPECT_EQ(mj.model->nv, nv);
  EXPECT_EQ(mj.model->nu, m);
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> control(-2.0, 2.0);
  std::vector<double> x(std::size_t(nq + nv)), xdot(x.size()), u(std::size_t(std::max(m, 1)));
  double worst = 0;
  for (int k = 0; k < count; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    std::copy(mj.data->qpos, mj.data->qpos + nq, x.begin());
    std::copy(mj.data->qvel, mj.data->qvel + nv, x.begin() + nq);
    for (int i = 0; i < m; ++i) mj.data->ctrl[i] = u[std::size_t(i)] = control(random);
    mj_forward(mj.model, mj.data);
    rhs(x.data(), u.data(), xdot.data());
    double size = 0, difference = 0;
    for (int i = 0; i < nv; ++i) {
      size = std::max(size, std::abs(mj.data->qacc[i]));
      difference = std::max(difference, std::abs(xdot[std::size_t(nq + i)] - mj.data->qacc[i]));
    }
    std::vector<double> rates = coordinate_rates(mj.model, mj.data->qpos, mj.data->qvel);
    for (int i = 0; i < nq; ++i) EXPECT_NEAR(xdot[std::size_t(i)], rates[std::size_t(i)], 1e-8) << "q'[" << i << "]";
    worst = std::max(worst, difference / size);
  }
  return worst;
}

// the generated model's rhs (with its default parameters) against mj_forward on `file`
template <class Parameters, class Rhs>
void expect_matches_mujoco(const std::string& file, int nq, int nv, int m, Rhs model_rhs) {
  MujocoModel mj(mjcf(file));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  // joint limits and contacts are what eomgen keeps as information only (a URDF's limits are on)
  mj.model->opt.disableflags |= mjDSBL_LIMIT | mjDSBL_CONTACT;
  // a URDF's inertias as it states them, not turned by MuJoCo's principal axes
  if (file.size() > 5 && file.compare(file.size() - 5, 5, ".urdf") == 0) with_stated_urdf_inertias(mj.model, mjcf(file));
  auto p = Parameters().values();
  auto rhs = [&](const double* x, const double* u, double* xdot) { model_rhs(0.0, x, u, p.data(), xdot); };
  double worst = worst_relative_difference(mj, nq, nv, m, rhs, 200);
  std::printf("%s: largest difference from MuJoCo's qacc: %.2g of its size\n", file.c_str(), worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0) << "two independent computations agree to the last bit at every state: suspicious";
}

// a generated model's namespace M: its rhs for double, its sizes and its parameters
#define EXPECT_MATCHES_MUJOCO(M)                                                                              \
  expect_matches_mujoco<eomgen::models::M::Parameters<double>>(                                              \
      #M ".xml", int(eomgen::models::M::num_coordinates), int(eomgen::models::M::num_velocities),            \
      int(eomgen::models::M::num_inputs), eomgen::models::M::rhs<double>)

TEST(MujocoOracle, ObliqueJointsThroughOffsetAnchorsMatchMujoco) { EXPECT_MATCHES_MUJOCO(oblique_tree); }

// the generated model's mass_matrix and forcing against MuJoCo's M (mj_fullM, armature included) and
// qfrc_passive + qfrc_actuator − qfrc_bias, to 1e-12 of their largest entries, at random states and controls
template <class Parameters, class MassMatrix, class Forcing>
void expect_mass_matrix_and_forcing_match_mujoco(const std::string& file, int nq, int nv, int m, MassMatrix mass_matrix,
                                                 Forcing forcing) {
  MujocoModel mj(mjcf(file));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  ASSERT_EQ(mj.model->nq, nq);
  ASSERT_EQ(mj.model->nv, nv);
  ASSERT_EQ(mj.model->nu, m);
  auto p = Parameters().values();
  std::mt19937 random(2028);
  std::uniform_real_distribution<double> control(-2.0, 2.0);
  std::vector<double> x(std::size_t(nq + nv)), u(std::size_t(std::max(m, 1))), M(std::size_t(nv * nv)), theirs(M.size());
  std::vector<double> f(static_cast<std::size_t>(nv));
  double worst = 0;
  for (int k = 0; k < 50; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    std::copy(mj.data->qpos, mj.data->qpos + nq, x.begin());
    std::copy(mj.data->qvel, mj.data->qvel + nv, x.begin() + nq);
    for (int i = 0; i < m; ++i) mj.data->ctrl[i] = u[std::size_t(i)] = control(random);
    mj_forward(mj.model, mj.data);
    mj_fullM(mj.model, theirs.data(), mj.data->qM);
    mass_matrix(0.0, x.data(), p.data(), M.data());
    forcing(0.0, x.data(), u.data(), p.data(), f.data());
    double M_size = 0, M_difference = 0, f_size = 0, f_difference = 0;
    for (std::size_t i = 0; i < M.size(); ++i) {
      M_size = std::max(M_size, std::abs(theirs[i]));
      M_difference = std::max(M_difference, std::abs(M[i] - theirs[i]));
    }
    for (int i = 0; i < nv; ++i) {
      double their_f = mj.data->qfrc_passive[i] + mj.data->qfrc_actuator[i] - mj.data->qfrc_bias[i];
      f_size = std::max(f_size, std::abs(their_f));
      f_difference = std::max(f_difference, std::abs(f[std::size_t(i)] - their_f));
    }
    worst = std::max({worst, M_difference / M_size, f_difference / f_size});
  }
  std::printf("%s: largest difference from MuJoCo's M and forces: %.2g of their size\n", file.c_str(), worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0) << "two independent computations agree to the last bit at every state: suspicious";
}

#define EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(M)                                                        \
  expect_mass_matrix_and_forcing_match_mujoco<eomgen::models::M::Parameters<double>>(                       \
      #M ".xml", int(eomgen::models::M::num_coordinates), int(eomgen::models::M::num_velocities),            \
      int(eomgen::models::M::num_inputs), eomgen::models::M::mass_matrix<double>,                            \
      eomgen::models::M::forcing<double>)

// M and f written out (the arm, the quadruped, floating_snake, the free body beside the humanoid) and
// by the world pass's loops over the links (the 21-joint trees, hinge_chain: emit/cpp_joint_tree.cpp)
TEST(MujocoOracle, MassMatricesAndForcesAreMujocos) {
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(seven_joint_arm);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(quadruped);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(floating_snake);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(branched_tree);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(hinge_chain);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(floating_humanoid);
  EXPECT_MASS_MATRIX_AND_FORCING_MATCH_MUJOCO(humanoid_beside_a_free_body);
}

// jacobian_state's ∂q''/∂(q, q') against central differences of MuJoCo's qacc in every qpos entry
// (MuJoCo turns by q/|q| as the header does, so a quaternion's raw components are directions too)
// and every qvel entry, at random states and controls: the closed-form derivatives of the tree
// recursions (the arm, the 21-joint tree, the quadruped) and the tangent sweep (the oblique tree)
template <class Parameters, class Jacobian>
void expect_jacobian_matches_mujoco(const std::string& file, int nq, int nv, int m, Jacobian model_jacobian) {
  MujocoModel mj(mjcf(file));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  mj.model->opt.disableflags |= mjDSBL_LIMIT | mjDSBL_CONTACT;
  auto p = Parameters().values();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> control(-2.0, 2.0);
  int n = nq + nv;
  std::vector<double> x(static_cast<std::size_t>(n)), J(static_cast<std::size_t>(n * n)),
      u(static_cast<std::size_t>(std::max(m, 1))), ahead(static_cast<std::size_t>(nv)), behind(static_cast<std::size_t>(nv));
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    for (int i = 0; i < m; ++i) mj.data->ctrl[i] = u[std::size_t(i)] = control(random);
    std::copy(mj.data->qpos, mj.data->qpos + nq, x.begin());
    std::copy(mj.data->qvel, mj.data->qvel + nv, x.begin() + nq);
    model_jacobian(0.0, x.data(), u.data(), p.data(), J.data());
    double size = 0, difference = 0;
    // mj_forward normalizes the quaternions of qpos in place: each evaluation starts from x
    auto accelerations = [&](int j, double step, std::vector<double>& qacc) {
      std::copy(x.begin(), x.begin() + nq, mj.data->qpos);
      std::copy(x.begin() + nq, x.end(), mj.data->qvel);
      (j < nq ? mj.data->qpos[j] : mj.data->qvel[j - nq]) += step;
      mj_forward(mj.model, mj.data);
      std::copy(mj.data->qacc, mj.data->qacc + nv, qacc.begin());
    };
    for (int j = 0; j < n; ++j) {
      double h = 1e-6 * std::max(1.0, std::abs(x[std::size_t(j)]));
      accelerations(j, h, ahead);
      accelerations(j, -h, behind);
      for (int i = 0; i < nv; ++i) {
        double ours = J[std::size_t((nq + i) * n + j)], central = (ahead[std::size_t(i)] - behind[std::size_t(i)]) / (2 * h);
        size = std::max(size, std::abs(ours));
        difference = std::max(difference, std::abs(ours - central));
      }
    }
    worst = std::max(worst, difference / size);
  }
  std::printf("%s: jacobian_state against MuJoCo's central differences: %.2g of its largest entry\n", file.c_str(), worst);
  // central differences with h = 1e-6 are good to about 1e-9 of the entries
  EXPECT_LT(worst, 1e-7);
}

#define EXPECT_JACOBIAN_MATCHES_MUJOCO(M)                                                                     \
  expect_jacobian_matches_mujoco<eomgen::models::M::Parameters<double>>(                                     \
      #M ".xml", int(eomgen::models::M::num_coordinates), int(eomgen::models::M::num_velocities),            \
      int(eomgen::models::M::num_inputs), eomgen::models::M::jacobian_state<double>)

TEST(MujocoOracle, JacobiansMatchMujocosDifferences) {
  EXPECT_JACOBIAN_MATCHES_MUJOCO(seven_joint_arm);
  EXPECT_JACOBIAN_MATCHES_MUJOCO(branched_tree);
  EXPECT_JACOBIAN_MATCHES_MUJOCO(quadruped);
  EXPECT_JACOBIAN_MATCHES_MUJOCO(oblique_tree);
}

// the robots of tests/crosscheck/models/: a 7-joint arm (a Panda's layout) and a humanoid-like
// tree of 21 hinges about oblique axes through offset anchors, both joint trees
TEST(MujocoOracle, SevenJointArmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(seven_joint_arm); }

TEST(MujocoOracle, BranchedTreeOf21ObliqueHingesMatchesMujoco) { EXPECT_MATCHES_MUJOCO(branched_tree); }

TEST(MujocoOracle, MeasuredArmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(measured_arm); }

// a chain of 12 oblique hinges, whose rhs is the articulated-body algorithm's (no M; JointTreeAccelerations
// checks that eomgen chooses it), armature included
TEST(MujocoOracle, LongChainSolvedByTheArticulatedBodyAlgorithmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(hinge_chain); }

// the same below a free joint (six columns at the root, D = L Δ Lᵀ), in MuJoCo's qpos and qvel layout
TEST(MujocoOracle, FloatingSnakeSolvedByTheArticulatedBodyAlgorithmMatchesMujoco) { EXPECT_MATCHES_MUJOCO(floating_snake); }

// a floating base: a free joint's position, quaternion and angular velocity in MuJoCo's layout,
// with twelve hinges below it; and the free tumbling body of models/
TEST(MujocoOracle, QuadrupedOnAFloatingBaseMatchesMujoco) { EXPECT_MATCHES_MUJOCO(quadruped); }

// the branched tree's 21 oblique hinges below a free torso: M and f by the loops, below a root joint
TEST(MujocoOracle, FloatingHumanoidMatchesMujoco) { EXPECT_MATCHES_MUJOCO(floating_humanoid); }

// two trees in one model, a free body and a hinged tree on the ground: the second tree's root link
// (its turn only in the gradient's tables) once lost its quantities to the header
TEST(MujocoOracle, AFreeBodyBesideAHingedTreeMatchesMujoco) { EXPECT_MATCHES_MUJOCO(humanoid_beside_a_free_body); }

TEST(MujocoOracle, FreeTumblingBodyMatchesMujoco) { EXPECT_MATCHES_MUJOCO(tumbling_body); }

// joints that follow another joint's coordinate (models/geared_gripper.toml: the right finger turns
// by −1.2 grip + 0.05, the counterweight slides by −0.04 shoulder) against MuJoCo's robot with the two
// as joints of their own: at its state with the followers placed so (qpos = m q + c, qvel = m q'),
// M = Jᵀ M_free J and f = Jᵀ (qfrc_passive + qfrc_actuator − qfrc_bias), J the constant gear ratios
TEST(MujocoOracle, JointsThatFollowACoordinateAreMujocosRobotGeared) {
  namespace robot = eomgen::models::geared_gripper;
  MujocoModel mj(mjcf("geared_gripper_free.xml"));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  const int n = int(robot::num_velocities), nv = mj.model->nv;
  ASSERT_EQ(n, 3);
  ASSERT_EQ(nv, 5);
  // MuJoCo's dofs (rack, shoulder, elbow, grip, right_grip) by ours (shoulder, elbow, grip): ratio, offset
  struct Follows {
    int coordinate;
    double ratio, offset;
  };
  const Follows dof[5] = {{0, -0.04, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {2, -1.2, 0.05}};
  auto p = robot::Parameters<double>().values();
  std::mt19937 random(2027);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0), control(-2.0, 2.0);
  std::vector<double> M(static_cast<std::size_t>(n * n)), f(static_cast<std::size_t>(n)), free_M(static_cast<std::size_t>(nv * nv));
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    double x[6], u[1] = {control(random)};
    for (int i = 0; i < 6; ++i) x[i] = i < n ? angle(random) : rate(random);
    for (int i = 0; i < nv; ++i) {
      mj.data->qpos[i] = dof[i].ratio * x[dof[i].coordinate] + dof[i].offset;
      mj.data->qvel[i] = dof[i].ratio * x[3 + dof[i].coordinate];
    }
    mj.data->ctrl[0] = u[0];
    mj_forward(mj.model, mj.data);
    mj_fullM(mj.model, free_M.data(), mj.data->qM);
    robot::mass_matrix(0.0, x, p.data(), M.data());
    robot::forcing(0.0, x, u, p.data(), f.data());
    double M_size = 0, f_size = 0, M_difference = 0, f_difference = 0;
    for (int a = 0; a < n; ++a) {
      double reduced_f = 0;
      for (int i = 0; i < nv; ++i)
        if (dof[i].coordinate == a)
          reduced_f += dof[i].ratio * (mj.data->qfrc_passive[i] + mj.data->qfrc_actuator[i] - mj.data->qfrc_bias[i]);
      f_size = std::max(f_size, std::abs(reduced_f));
      f_difference = std::max(f_difference, std::abs(f[std::size_t(a)] - reduced_f));
      for (int b = 0; b < n; ++b) {
        double reduced_M = 0;
        for (int i = 0; i < nv; ++i)
          for (int j = 0; j < nv; ++j)
            if (dof[i].coordinate == a && dof[j].coordinate == b) reduced_M += dof[i].ratio * free_M[std::size_t(i * nv + j)] * dof[j].ratio;
        M_size = std::max(M_size, std::abs(reduced_M));
        M_difference = std::max(M_difference, std::abs(M[std::size_t(a * n + b)] - reduced_M));
      }
    }
    worst = std::max({worst, M_difference / M_size, f_difference / f_size});
  }
  std::printf("geared_gripper: largest difference from MuJoCo's reduced M and f: %.2g of their size\n", worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0) << "two independent computations agree to the last bit at every state: suspicious";
}

// a floating base's horizontal momenta, which the header forms from the row of M (their chain rule
// through the tree is long: derive/equations.hpp, FirstIntegral), are the robot's linear momentum as
// MuJoCo has it: its subtree's mass times the velocity of its centre of mass (mj_subtreeVel)
TEST(MujocoOracle, AFloatingBasesMomentaAreMujocosLinearMomentum) {
  namespace robot = eomgen::models::quadruped;
  ASSERT_EQ(robot::num_first_integrals, 2u);
  EXPECT_STREQ(robot::first_integral_names[0], "p_x");
  EXPECT_STREQ(robot::first_integral_names[1], "p_y");
  MujocoModel mj(mjcf("quadruped.xml"));
  ASSERT_NE(mj.model, nullptr) << mj.message;
  auto p = robot::Parameters<double>().values();
  std::mt19937 random(11);
  std::vector<double> x(robot::num_states);
  double out[2];
  for (int k = 0; k < 20; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    std::copy(mj.data->qpos, mj.data->qpos + mj.model->nq, x.begin());
    std::copy(mj.data->qvel, mj.data->qvel + mj.model->nv, x.begin() + mj.model->nq);
    mj_forward(mj.model, mj.data);
    mj_subtreeVel(mj.model, mj.data);
    robot::first_integrals(0.0, x.data(), p.data(), out);
    // the robot's mass times its fastest rate: the size of a momentum at this state
    double mass = mj.model->body_subtreemass[1], fastest = 0;
    for (int i = 0; i < mj.model->nv; ++i) fastest = std::max(fastest, std::abs(mj.data->qvel[i]));
    for (int i = 0; i < 2; ++i) {
      double momentum = mass * mj.data->subtree_linvel[3 + i];
      EXPECT_NEAR(out[i], momentum, 1e-12 * mass * fastest) << "state " << k << ", p[" << i << "]";
    }
  }
}

// `eomgen import` of the same MJCF files (tests/CMakeLists.txt imports and generates them): the model
// file it writes gives MuJoCo's accelerations, motors included
#define EXPECT_IMPORT_MATCHES_MUJOCO(M)                                                                     \
  expect_matches_mujoco<eomgen::models::M##_imported::Parameters<double>>(                                \
      #M ".xml", int(eomgen::models::M##_imported::num_coordinates),                                      \
      int(eomgen::models::M##_imported::num_velocities), int(eomgen::models::M##_imported::num_inputs),     \
      eomgen::models::M##_imported::rhs<double>)

TEST(MujocoImport, SevenJointArmImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(seven_joint_arm); }
TEST(MujocoImport, QuadrupedImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(quadruped); }
TEST(MujocoImport, ObliqueTreeImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(oblique_tree); }
TEST(MujocoImport, MeasuredArmImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(measured_arm); }
TEST(MujocoImport, FreeBodyImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(tumbling_body); }

// defaults and classes, degrees, euler angles in zyx, axisangle, xyaxes, zaxis, inertias from geoms,
// a free and a ball joint, two hinges in one body, armature, damping, a spring, geared motors
TEST(MujocoImport, MjcfFeaturesImportAndMatchMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(mjcf_features); }

// a ball below a ball, in a body that also slides, and a hinge below
TEST(MujocoImport, BallBelowABallImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(ball_chain); }

// a floating ragdoll of seven ball joints and four oblique hinges, whose M and f, like its gradient,
// come from the loops over its links (links of three columns)
TEST(MujocoImport, ABallJointedRagdollImportsAndMatchesMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(ball_ragdoll); }

// several trees side by side, each from a joint of several velocities (a robot beside free objects,
// as dm_control's dog and its ball): the loops take them all, each root's motion straight-line, over
// links of one column (the snake) and of three (the ragdoll, and a lamp hung from a ball joint)
TEST(MujocoImport, TreesBesideFreeObjectsImportAndMatchMujoco) {
  EXPECT_IMPORT_MATCHES_MUJOCO(snake_beside_free_objects);
  EXPECT_IMPORT_MATCHES_MUJOCO(ragdoll_beside_free_objects);
}

// position, velocity and affine servos beside a motor: each a generalized force affine in u, q and q'
TEST(MujocoImport, ServosImportAndMatchMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(servo_arm); }

// actuators on fixed tendons: a servo on the two fingers' ½ q1 + ½ q2 (as mujoco_menagerie's Panda
// hand), a force-limited motor on 2 q1 − 0.3 q3, and a motor on a joint
TEST(MujocoImport, ActuatorsOnFixedTendonsImportAndMatchMujoco) { EXPECT_IMPORT_MATCHES_MUJOCO(tendon_gripper); }

// gravity, the passive forces (springs, dampers and a medium) and the clamping of controls switched
// off by the file's <option> flags: the model without them moves as MuJoCo's
TEST(MujocoImport, ForcesSwitchedOffByTheFileAreLeftOut) { EXPECT_IMPORT_MATCHES_MUJOCO(switched_off_forces); }

// MuJoCo 2.3's gravcomp, which MuJoCo 2.2.2 cannot read: the imported model against MuJoCo reading the
// file without it, the force −gravcomp m g at each body's centre of mass put in xfrc_applied (which
// MuJoCo applies there); the bodies and their parts as the file states them
template <class Parameters, class Rhs>
void expect_compensation_matches_mujoco(const std::string& file, const std::vector<std::pair<std::string, double>>& parts, int nq,
                                        int nv, int nu, Rhs model_rhs) {
  std::stringstream text;
  text << std::ifstream(mjcf(file)).rdbuf();
  std::string without = std::regex_replace(text.str(), std::regex(R"( gravcomp="[^"]*")"), "");
  ASSERT_NE(without, text.str());
  std::string path = (std::filesystem::temp_directory_path() / ("without_gravcomp_" + file)).string();
  std::ofstream(path) << without;
  MujocoModel mj(path);
  ASSERT_NE(mj.model, nullptr) << mj.message;
  auto p = Parameters().values();
  auto rhs = [&](const double* x, const double* u, double* xdot) { model_rhs(0.0, x, u, p.data(), xdot); };
  double uncompensated = worst_relative_difference(mj, nq, nv, nu, rhs, 20);
  for (const auto& [name, part] : parts) {
    // an unnamed body by its number
    int body = std::isdigit(static_cast<unsigned char>(name[0])) ? std::stoi(name) : mj_name2id(mj.model, mjOBJ_BODY, name.c_str());
    ASSERT_GT(body, 0) << name;
    for (int k = 0; k < 3; ++k) mj.data->xfrc_applied[6 * body + k] = -mj.model->opt.gravity[k] * mj.model->body_mass[body] * part;
  }
  double worst = worst_relative_difference(mj, nq, nv, nu, rhs, 200);
  std::printf("%s: largest difference from MuJoCo's qacc: %.2g of its size (%.2g without the compensation)\n", file.c_str(),
              worst, uncompensated);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0);
  EXPECT_GT(uncompensated, 1e-2) << "the compensation moves the robot";
}

#define EXPECT_COMPENSATION_MATCHES_MUJOCO(M, ...)                                                            \
  expect_compensation_matches_mujoco<eomgen::models::M##_imported::Parameters<double>>(                     \
      #M ".xml", __VA_ARGS__, int(eomgen::models::M##_imported::num_coordinates),                            \
      int(eomgen::models::M##_imported::num_velocities), int(eomgen::models::M##_imported::num_inputs),      \
      eomgen::models::M##_imported::rhs<double>)

// parts of 1, ½ and ¼ (the third body unnamed): a force at each centre of mass
TEST(MujocoImport, GravityCompensationIsAForceAtEachCentreOfMass) {
  EXPECT_COMPENSATION_MATCHES_MUJOCO(gravity_compensated_arm, {{"base", 1.0}, {"upper", 0.5}, {"3", 0.25}});
}

// ¾ of every moving body's weight: gravity of a quarter
TEST(MujocoImport, OneGravityCompensationForEveryMovingBodyIsLessGravity) {
  EXPECT_COMPENSATION_MATCHES_MUJOCO(evenly_compensated_arm, {{"shoulder", 0.75}, {"upper", 0.75}, {"fore", 0.75}});
}

// MuJoCo 3's actuatorfrcrange, which MuJoCo 2.2.2 cannot read: the imported model against MuJoCo reading
// the file without it, its qfrc_actuator clamped here per joint (the ranges as the file states them)
// and the accelerations formed again from it (mj_fwdAcceleration); the controls of ±2 drive the
// motors past the ranges
TEST(MujocoImport, AJointsTotalActuatorForceIsClampedToItsRange) {
  namespace robot = eomgen::models::joint_force_ranges_imported;
  std::stringstream text;
  text << std::ifstream(mjcf("joint_force_ranges.xml")).rdbuf();
  std::string without = std::regex_replace(text.str(), std::regex(R"( actuatorfrc(range|limited)="[^"]*")"), "");
  std::string path = (std::filesystem::temp_directory_path() / "without_actuatorfrcrange.xml").string();
  std::ofstream(path) << without;
  MujocoModel mj(path);
  ASSERT_NE(mj.model, nullptr) << mj.message;
  const std::pair<const char*, std::array<double, 2>> ranges[] = {{"hip", {-5, 5}}, {"knee", {-2, 3}}};
  ASSERT_EQ(mj.model->nq, int(robot::num_coordinates));
  auto p = robot::Parameters<double>().values();
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> control(-2.0, 2.0);
  std::vector<double> x(std::size_t(mj.model->nq + mj.model->nv)), xdot(x.size()), u(std::size_t(mj.model->nu));
  double worst = 0;
  int clamped = 0;
  for (int k = 0; k < 200; ++k) {
    random_state(mj.model, random, mj.data->qpos, mj.data->qvel);
    std::copy(mj.data->qpos, mj.data->qpos + mj.model->nq, x.begin());
    std::copy(mj.data->qvel, mj.data->qvel + mj.model->nv, x.begin() + mj.model->nq);
    for (int i = 0; i < mj.model->nu; ++i) mj.data->ctrl[i] = u[std::size_t(i)] = control(random);
    mj_forward(mj.model, mj.data);
    for (const auto& [joint, range] : ranges) {
      double& force = mj.data->qfrc_actuator[mj.model->jnt_dofadr[mj_name2id(mj.model, mjOBJ_JOINT, joint)]];
      clamped += force < range[0] || force > range[1];
      force = std::clamp(force, range[0], range[1]);
    }
    mj_fwdAcceleration(mj.model, mj.data);
    robot::rhs(0.0, x.data(), u.data(), p.data(), xdot.data());
    double size = 0, difference = 0;
    for (int i = 0; i < mj.model->nv; ++i) {
      size = std::max(size, std::abs(mj.data->qacc_smooth[i]));
      difference = std::max(difference, std::abs(xdot[std::size_t(mj.model->nq + i)] - mj.data->qacc_smooth[i]));
    }
    worst = std::max(worst, difference / size);
  }
  std::printf("joint_force_ranges.xml: largest difference from MuJoCo's clamped qacc: %.2g of its size (%d clamps)\n", worst,
              clamped);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst, 0.0);
  EXPECT_GT(clamped, 100) << "the ranges bind";
}

// URDF, read by the same compiler: inertial origins with rpy and full tensors, joint origins with rpy,
// an oblique axis; and the seven-joint arm as URDF (without armature and motors, which URDF lacks)
#define EXPECT_URDF_IMPORT_MATCHES_MUJOCO(M)                                                                  \
  expect_matches_mujoco<eomgen::models::M##_from_urdf::Parameters<double>>(                                 \
      "urdf/" #M ".urdf", int(eomgen::models::M##_from_urdf::num_coordinates),                                \
      int(eomgen::models::M##_from_urdf::num_velocities), int(eomgen::models::M##_from_urdf::num_inputs),     \
      eomgen::models::M##_from_urdf::rhs<double>)

TEST(MujocoImport, UrdfArmImportsAndMatchesMujoco) { EXPECT_URDF_IMPORT_MATCHES_MUJOCO(two_link_arm); }
TEST(MujocoImport, SevenJointArmAsUrdfImportsAndMatchesMujoco) { EXPECT_URDF_IMPORT_MATCHES_MUJOCO(seven_joint_arm); }

// a URDF's two-axis shoulder, two joints with a massless link between them, which MuJoCo refuses
// (eomgen reads it with the compiler's mass bounds, import/massless_bodies.hpp): against the MJCF
// arm with both joints in one body
TEST(MujocoImport, AMasslessLinkBetweenTwoJointsImportsAndMatchesMujoco) {
  namespace robot = eomgen::models::two_axis_shoulder_from_urdf;
  expect_matches_mujoco<robot::Parameters<double>>("two_axis_shoulder.xml", int(robot::num_coordinates), int(robot::num_velocities),
                                                   int(robot::num_inputs), robot::rhs<double>);
}

}  // namespace
