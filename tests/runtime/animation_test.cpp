// The animation's parts without a browser: the header's body_poses against the models' known
// kinematics, the recorder and the scene it implies (rods, the view of a planar motion), the
// quaternion of a rotation, and the page's refusals. tests/animation/ opens the pages in Chromium.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "generated/header_registry.hpp"
#include "report/animation.hpp"

namespace eomgen::test {
namespace {

std::size_t body_index(const eomgen_model_abi& m, const std::string& name) {
  for (std::size_t b = 0; b < m.num_drawn_bodies; ++b)
    if (name == m.drawn_body_names[b]) return b;
  ADD_FAILURE() << m.name << " draws no " << name;
  return 0;
}

std::vector<double> poses_at(const eomgen_model_abi& m, const std::vector<double>& x) {
  std::vector<double> out(12 * m.num_drawn_bodies);
  m.body_poses(0.0, x.data(), m.default_parameters, out.data());
  return out;
}

TEST(Animation, DoublePendulumBobsAreWhereTheModelPutsThemAndHangFromEachOther) {
  const eomgen_model_abi& m = *generated_model("double_pendulum").abi;
  ASSERT_EQ(m.num_drawn_bodies, 2u);
  std::size_t bob1 = body_index(m, "bob1"), bob2 = body_index(m, "bob2");
  EXPECT_EQ(m.drawn_body_parents[bob1], -1);
  EXPECT_EQ(m.drawn_body_parents[bob2], int(bob1));  // the tree of particles
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3, 3);
  const double* p = m.default_parameters;  // m1, m2, l1, l2, g
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> x{angle(random), angle(random), 0, 0};
    auto pose = poses_at(m, x);
    double tip[3] = {p[2] * std::sin(x[0]) + p[3] * std::sin(x[1]), -p[2] * std::cos(x[0]) - p[3] * std::cos(x[1]), 0};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(pose[12 * bob2 + std::size_t(i)], tip[i], 1e-15);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(pose[12 * bob2 + 3 + std::size_t(i)], i % 4 == 0 ? 1.0 : 0.0);
  }
}

// the top's axes turned by the 3-1-3 Euler angles: R = rot_z(ψ) rot_x(θ) rot_z(φ), written out here
TEST(Animation, TopTurnsByItsEulerAnglesAndCarriesItsShapes) {
  const eomgen_model_abi& m = *generated_model("heavy_symmetric_top").abi;
  std::size_t top = body_index(m, "top");
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-3, 3);
  for (int trial = 0; trial < 20; ++trial) {
    double psi = angle(random), theta = angle(random), phi = angle(random);
    auto pose = poses_at(m, {psi, theta, phi, 0, 0, 0});
    double cp = std::cos(psi), sp = std::sin(psi), ct = std::cos(theta), st = std::sin(theta), cf = std::cos(phi), sf = std::sin(phi);
    double R[9] = {cp * cf - sp * ct * sf, -cp * sf - sp * ct * cf, sp * st,
                   sp * cf + cp * ct * sf, -sp * sf + cp * ct * cf, -cp * st,
                   st * sf, st * cf, ct};
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(pose[12 * top + 3 + std::size_t(i)], R[i], 1e-14) << i;
    auto q = runtime::rotation_quaternion(&pose[12 * top + 3]);
    // q turns the body's axis of symmetry e_z onto the third column of R
    double w = q[0], a = q[1], b = q[2], c = q[3];
    double axis[3] = {2 * (a * c + w * b), 2 * (b * c - w * a), 1 - 2 * (a * a + b * b)};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(axis[i], R[3 * i + 2], 1e-14);
  }
  ASSERT_EQ(m.num_drawn_shapes, 2u);  // the disc and the stem of the model file
  std::vector<double> shapes(18 * m.num_drawn_shapes);
  m.drawn_shapes(m.default_parameters, shapes.data());
  EXPECT_EQ(m.drawn_shape_types[0], 3);  // a cylinder
  EXPECT_NEAR(shapes[18 + 1], m.default_parameters[1], 0);  // the stem is s long
  for (int i = 0; i < 9; ++i) EXPECT_EQ(shapes[18 + 9 + std::size_t(i)], i % 4 == 0 ? 1.0 : 0.0) << "not turned: R = I";
}

TEST(Animation, QuaternionOfARotationIsExactForEveryCaseOfShepperdsMethod) {
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    double q[4] = {normal(random), normal(random), normal(random), normal(random)};
    if (trial % 4) q[trial % 4] *= 50;  // each component the largest in turn
    double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= n;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    auto back = runtime::rotation_quaternion(R);
    double sign = back[0] * w + back[1] * x + back[2] * y + back[3] * z < 0 ? -1 : 1;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(sign * back[std::size_t(i)], q[i], 1e-14);
  }
}

runtime::AnimationRecorder recorded_run(const eomgen_model_abi& m, double t_end, std::size_t max_frames = 6000) {
  runtime::Problem problem;
  problem.model = &m;
  problem.parameters.assign(m.default_parameters, m.default_parameters + m.num_parameters);
  problem.inputs.assign(m.default_inputs, m.default_inputs + m.num_inputs);
  runtime::SimulationSettings settings;
  settings.t_end = t_end, settings.dt_out = 0.01, settings.integrator = "arkode-dp5";
  runtime::AnimationRecorder recorder(m, problem.parameters, max_frames);
  settings.stream = [&](const runtime::Trajectory& rows) { return recorder.take(rows), true; };
  std::vector<double> x0(m.default_state, m.default_state + m.num_states);
  runtime::SimulationResult result = runtime::simulate(problem, x0, settings);
  EXPECT_FALSE(result.failed) << result.failure;
  return recorder;
}

TEST(Animation, DoublePendulumSceneHasItsTwoRodsAndIsSeenFromItsPlanesNormal) {
  const eomgen_model_abi& m = *generated_model("double_pendulum").abi;
  auto recorder = recorded_run(m, 2);
  EXPECT_EQ(recorder.frames(), 201u);
  runtime::AnimationScene scene = runtime::animation_scene(recorder);
  std::size_t bob1 = body_index(m, "bob1"), bob2 = body_index(m, "bob2");
  ASSERT_EQ(scene.rods.size(), 2u);
  EXPECT_EQ(scene.rods[0], (std::array<int, 2>{int(bob1), -1}));
  EXPECT_EQ(scene.rods[1], (std::array<int, 2>{int(bob2), int(bob1)}));
  EXPECT_TRUE(scene.planar);
  EXPECT_EQ(scene.view, (std::array<double, 3>{0, 0, -1}));
  EXPECT_EQ(scene.up, (std::array<double, 3>{0, 1, 0}));  // against gravity, −y
  EXPECT_GT(scene.radius, 0.5);
  EXPECT_LT(scene.radius, 2.5);
}

// a free body that falls travels far beyond its own size: the view follows it; the pendulum stays put
TEST(Animation, AFallingBodyIsFollowedAndAPendulumIsNot) {
  const eomgen_model_abi& body = *generated_model("tumbling_body").abi;
  runtime::AnimationScene falling = runtime::animation_scene(recorded_run(body, 3));
  EXPECT_TRUE(falling.follow);
  EXPECT_LT(4 * falling.radius, falling.extent);
  EXPECT_FALSE(falling.planar);
  EXPECT_NEAR(falling.up[2], 1, 1e-15);  // against gravity, −z
  runtime::AnimationScene pendulum = runtime::animation_scene(recorded_run(*generated_model("double_pendulum").abi, 2));
  EXPECT_FALSE(pendulum.follow);
  EXPECT_EQ(pendulum.extent, pendulum.radius);
  EXPECT_LT(pendulum.floor, -1.0);  // the lowest bob, below the centre of the scene
}

TEST(Animation, LongRunsKeepAtMostTwiceTheFramesAskedForEvenlySpaced) {
  const eomgen_model_abi& m = *generated_model("double_pendulum").abi;
  auto recorder = recorded_run(m, 10, 100);
  EXPECT_LE(recorder.frames(), 200u);
  EXPECT_GE(recorder.frames(), 100u);
  double interval = recorder.times()[1] - recorder.times()[0];
  for (std::size_t f = 1; f < recorder.frames(); ++f)
    EXPECT_NEAR(recorder.times()[f] - recorder.times()[f - 1], interval, 1e-9);
}

TEST(Animation, PageRefusesATraceOfNoBodyAndNamesTheBodiesThereAre) {
  const eomgen_model_abi& m = *generated_model("double_pendulum").abi;
  auto recorder = recorded_run(m, 0.1);
  std::string error;
  runtime::AnimationSettings settings;
  settings.trace = {"tip"};
  EXPECT_EQ(runtime::animation_page(recorder, settings, error), "");
  EXPECT_NE(error.find("--trace tip"), std::string::npos) << error;
  EXPECT_NE(error.find("bob1, bob2"), std::string::npos) << error;
  error.clear();
  settings.trace = {"bob2"};
  std::string page = runtime::animation_page(recorder, settings, error);
  EXPECT_EQ(error, "");
  EXPECT_NE(page.find("\"trace\":[1]"), std::string::npos);
  EXPECT_EQ(page.find("%%EOMGEN_"), std::string::npos);  // every placeholder filled
}

}  // namespace
}  // namespace eomgen::test
