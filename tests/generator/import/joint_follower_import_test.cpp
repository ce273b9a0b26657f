// A URDF mimic and an MJCF linear joint coupling import as a joint that follows the other's
// coordinate (generator/import/joint_followers.hpp). The oracle is the same robot imported without
// the coupling, where the follower has a coordinate of its own: with the follower's angle
// θ = m q + c and rate m q', the map J from the follower model's velocities to the free model's
// gives M = Jᵀ M_free J and f = Jᵀ f_free (J is constant, so no J' q' term), at random states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>

#include <fmt/format.h>

#include "import/model_writer.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

// an arm whose forearm carries two fingers, in two branches, the right one mimicking the left
// (both damped); ROOT is a fixed or a floating joint to the world
const char* const fingered_arm = R"(<?xml version="1.0"?>
<robot name="fingered">
  <link name="world"/>
  <link name="upper">
    <inertial><origin xyz="0.02 0 0.15" rpy="0.1 0.2 0"/><mass value="1.4"/>
      <inertia ixx="0.02" ixy="0.001" ixz="-0.002" iyy="0.025" iyz="0.0005" izz="0.006"/></inertial>
  </link>
  <link name="fore">
    <inertial><origin xyz="0 0.01 0.12"/><mass value="0.8"/>
      <inertia ixx="0.008" ixy="0" ixz="0.0004" iyy="0.009" iyz="0" izz="0.002"/></inertial>
  </link>
  <link name="left">
    <inertial><origin xyz="0.01 0 0.04"/><mass value="0.12"/>
      <inertia ixx="0.0002" ixy="0" ixz="0" iyy="0.00018" iyz="0.00001" izz="0.00004"/></inertial>
  </link>
  <link name="right">
    <inertial><origin xyz="-0.01 0 0.035"/><mass value="0.1"/>
      <inertia ixx="0.00015" ixy="0" ixz="0" iyy="0.00016" iyz="0" izz="0.00003"/></inertial>
  </link>
  <joint name="root" type="ROOT"><parent link="world"/><child link="upper"/><origin xyz="0 0 0.5"/></joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0 0.03 0.3" rpy="0.3 0 0"/><axis xyz="1 0 1"/>
    <limit lower="-2" upper="2" effort="50" velocity="3"/><dynamics damping="0.3"/>
  </joint>
  <joint name="left_finger" type="revolute">
    <parent link="fore"/><child link="left"/><origin xyz="0.03 0.02 0.25"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="3"/><dynamics damping="0.02"/>
  </joint>
  <joint name="right_finger" type="revolute">
    <parent link="fore"/><child link="right"/><origin xyz="-0.03 0.02 0.25" rpy="0 0 0.4"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="3"/><dynamics damping="0.05"/>
    MIMIC
  </joint>
</robot>
)";

std::string fingered(const std::string& root, bool mimic) {
  std::string text = fingered_arm;
  text.replace(text.find("ROOT"), 4, root);
  text.replace(text.find("MIMIC"), 5, mimic ? "<mimic joint=\"left_finger\" multiplier=\"-1.5\" offset=\"0.1\"/>" : "");
  return text;
}

std::string imported(const std::string& file_text, const std::string& name) {
  std::string path = temporary_directory() + "/" + name;
  std::ofstream(path) << file_text;
  Diagnostics diagnostics;
  auto text = imported_model_text(path, diagnostics, false);
  EXPECT_TRUE(text) << diagnostics.format();
  return text ? *text : "";
}

// the velocity names of a model (der(q), or a ball's or free joint's ω components)
std::vector<std::string> velocity_names(const Equations& e) {
  std::vector<std::string> names;
  for (const GiNaC::realsymbol& v : e.symbols.velocities) names.push_back(v.get_name());
  return names;
}

std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
  return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
}

// M = Jᵀ M_free J and f = Jᵀ f_free, the follower `follower` = m·`leader` + c; a quaternion's
// coordinates start at unit length and the rest at random
void expect_reduction(const std::string& follower_text, const std::string& free_text, const std::string& leader,
                      const std::string& follower, double m, double c) {
  Equations reduced = derive_text(follower_text, "follower.toml"), full = derive_text(free_text, "free.toml");
  std::vector<std::string> v = velocity_names(reduced), v_full = velocity_names(full);
  ASSERT_EQ(v_full.size(), v.size() + 1);
  std::size_t n = v.size(), n_full = v_full.size();
  // J: the free model's velocity i is J(i, a) times the follower model's velocity a
  std::vector<std::vector<double>> J(n_full, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n_full; ++i)
    if (v_full[i] == "der(" + follower + ")") J[i][index_of(v, "der(" + leader + ")")] = m;
    else J[i][index_of(v, v_full[i])] = 1;
  std::mt19937 random(23);
  std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-2, 2);
  for (int point = 0; point < 8; ++point) {
    std::map<std::string, double> values;
    for (const std::string& q : reduced.symbols.coordinate_names) values[q] = angle(random);
    for (const std::string& w : v) values[w] = rate(random);
    for (const std::string& q : reduced.symbols.coordinate_names)  // unit quaternions
      if (q.size() > 3 && q.compare(q.size() - 3, 3, "_qw") == 0) {
        std::string stem = q.substr(0, q.size() - 2);
        double norm = 0;
        for (const char* k : {"qw", "qx", "qy", "qz"}) norm += values[stem + k] * values[stem + k];
        for (const char* k : {"qw", "qx", "qy", "qz"}) values[stem + k] /= std::sqrt(norm);
      }
    std::map<std::string, double> free_values = values;
    free_values[follower] = m * values.at(leader) + c;
    free_values["der(" + follower + ")"] = m * values.at("der(" + leader + ")");
    GiNaC::exmap at = point_by_name(reduced, values), at_full = point_by_name(full, free_values);
    // the controls, the same by name in both
    for (std::size_t i = 0; i < reduced.symbols.inputs.size(); ++i) {
      double u = rate(random);
      at[reduced.symbols.inputs[i]] = u;
      at_full[full.symbols.inputs[index_of(full.symbols.input_names, reduced.symbols.input_names[i])]] = u;
    }
    std::vector<std::vector<double>> M_full(n_full, std::vector<double>(n_full));
    std::vector<double> f_full(n_full);
    double M_scale = 0, f_scale = 0;
    for (std::size_t i = 0; i < n_full; ++i) {
      f_full[i] = value_at(full.forcing[i], at_full);
      f_scale = std::max(f_scale, std::abs(f_full[i]));
      for (std::size_t j = 0; j < n_full; ++j)
        M_full[i][j] = value_at(full.mass_matrix(unsigned(i), unsigned(j)), at_full), M_scale = std::max(M_scale, std::abs(M_full[i][j]));
    }
    for (std::size_t a = 0; a < n; ++a) {
      double f = 0;
      for (std::size_t i = 0; i < n_full; ++i) f += J[i][a] * f_full[i];
      EXPECT_NEAR(value_at(reduced.forcing[a], at), f, 1e-12 * f_scale) << "f[" << v[a] << "] at " << point;
      for (std::size_t b = 0; b < n; ++b) {
        double M = 0;
        for (std::size_t i = 0; i < n_full; ++i)
          for (std::size_t j = 0; j < n_full; ++j) M += J[i][a] * M_full[i][j] * J[j][b];
        EXPECT_NEAR(value_at(reduced.mass_matrix(unsigned(a), unsigned(b)), at), M, 1e-12 * M_scale)
            << "M[" << v[a] << "][" << v[b] << "] at " << point;
      }
    }
  }
}

TEST(JointFollowerImport, AMimicJointFollowsTheCoordinateItMimics) {
  std::string text = imported(fingered("fixed", true), "fingered.urdf");
  for (const char* line : {"# joint 'right_finger' follows the coordinate 'left_finger' (a mimic or linear coupling)",
                           "coordinate = \"left_finger\", multiplier = -1.5, offset = 0.1 }",
                           "dissipation = \"(0.3*der(elbow)^2 + 0.02*der(left_finger)^2 + 0.05*(-1.5*der(left_finger))^2)/2\""})
    EXPECT_NE(text.find(line), std::string::npos) << line << " in\n" << text;
  EXPECT_EQ(text.find("right_finger ="), std::string::npos) << "the follower has no coordinate:\n" << text;
  EXPECT_EQ(text.find("[[constraints]]"), std::string::npos) << text;
  EXPECT_EQ(text.find("lagrange1"), std::string::npos) << text;
  expect_reduction(text, imported(fingered("fixed", false), "free_fingers.urdf"), "left_finger", "right_finger", -1.5, 0.1);
}

// on a floating base (Appell's equations over the tree, pseudo-velocities) it follows as well, where
// a constraint could not be carried
TEST(JointFollowerImport, AMimicJointOnAFloatingBaseFollowsToo) {
  std::string text = imported(fingered("floating", true), "floating_fingered.urdf");
  EXPECT_NE(text.find("coordinate = \"left_finger\", multiplier = -1.5, offset = 0.1 }"), std::string::npos) << text;
  EXPECT_EQ(text.find("not carried: right_finger"), std::string::npos) << text;
  expect_reduction(text, imported(fingered("floating", false), "floating_free_fingers.urdf"), "left_finger", "right_finger",
                   -1.5, 0.1);
}

// MuJoCo's q1 − q1₀ = c0 + c1 (q2 − q2₀), linear: the follower turns by c1 q2 + q1₀ + c0 − c1 q2₀ in
// the model's angles, which are MuJoCo's qpos (a reference of 0.2 on the follower, 0.1 on the leader);
// a servo on the follower pulls on the leader with c1 times its force
TEST(JointFollowerImport, ALinearJointCouplingIsAFollowerAndAQuadraticOneAConstraint) {
  std::string robot = R"xml(<mujoco model="geared">
  <compiler angle="radian"/>
  <worldbody>
    <body name="driver" pos="0 0 1">
      <joint name="b" type="hinge" axis="0 1 0" ref="0.1" damping="0.2"/>
      <geom type="capsule" fromto="0 0 0 0.1 0 -0.3" size="0.02" mass="1" contype="0" conaffinity="0"/>
      <body name="driven" pos="0.1 0 -0.3">
        <joint name="a" type="hinge" axis="1 0 1" ref="0.2" armature="0.01" stiffness="3"/>
        <geom type="capsule" fromto="0 0 0 0 0.05 -0.2" size="0.02" mass="0.6" contype="0" conaffinity="0"/>
      </body>
    </body>
    <body name="slider" pos="1 0 1">
      <joint name="s" type="slide" axis="1 0 0"/>
      <joint name="r" type="hinge" axis="0 0 1"/>
      <geom type="box" size="0.05 0.02 0.02" pos="0.1 0 0" mass="0.5" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <equality>EQUALITY</equality>
  <actuator><position name="driven_servo" joint="a" kp="3"/></actuator>
</mujoco>)xml";
  auto with = [&](const std::string& equality) {
    std::string text = robot;
    text.replace(text.find("EQUALITY"), 8, equality);
    return text;
  };
  std::string text = imported(with(R"(<joint name="gear" joint1="a" joint2="b" polycoef="0.1 -2 0 0 0"/>
    <joint name="rack" joint1="s" joint2="r" polycoef="0 0.05 0.01 0 0"/>)"), "geared.xml");
  // offset 0.2 + 0.1 − (−2)(0.1) = 0.5
  EXPECT_NE(text.find("coordinate = \"b\", multiplier = -2, offset = 0.5 }"), std::string::npos) << text;
  EXPECT_NE(text.find("name = \"rack\"\nholonomic = \"s - 0.05*r - 0.01*r^2\""), std::string::npos) << text;
  EXPECT_NE(text.find("method = \"lagrange1\""), std::string::npos) << "the quadratic coupling stays a constraint";
  std::string linear = imported(with(R"(<joint name="gear" joint1="a" joint2="b" polycoef="0.1 -2 0 0 0"/>)"), "gear.xml");
  EXPECT_EQ(linear.find("[[constraints]]"), std::string::npos) << linear;
  expect_reduction(linear, imported(with(""), "free_gear.xml"), "b", "a", -2, 0.5);
}

}  // namespace
}  // namespace eomgen::test
