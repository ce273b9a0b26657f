// Ball and free joints (model/build_spherical_joints.cpp, spatial/joint_velocities.hpp): a unit
// quaternion as coordinates and the angular velocity in the body's axes as velocities.
// - generated/ball_joint_top.hpp (an asymmetric top on a ball joint whose pivot is not its frame's
//   origin) satisfies Euler's equations about the pivot with the gravity moment, at random states;
// - generated/tumbling_body.hpp (a free body): M = diag(m, m, m, A, B, C), the centre falls with g,
//   ω' follows Euler's equations, q' = ½ q ⊗ (0, ω), and a quaternion of any length is the same
//   orientation;
// - a kinetic energy written in the quaternion's rates (an armature) is an inertia about the pivot;
// - misuses of the joint are located, with a fix, and so is a ball joint in a model that is no tree;
// - generated/ball_spring_top.hpp (the top held by ½k θ², rotation_angle): the spring's generalized
//   force is −k θ·axis of the turn, at the rest pose, at turns of 1e-9 and on both sides of
//   atan_ratio's cut, at a half turn and for a quaternion of any length and sign, and its Jacobian
//   there is the central differences' of its rhs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <random>

#include <Eigen/Dense>

#include "pipeline.hpp"
#include "support/test_support.hpp"

#include "../generated/ball_joint_top.hpp"
#include "../generated/ball_spring_top.hpp"
#include "../generated/tumbling_body.hpp"

namespace eomgen::test {
namespace {

using Vector = Eigen::Vector3d;
using Matrix = Eigen::Matrix3d;

// R(q) of a unit quaternion w, x, y, z: body components to inertial
Matrix rotation_of(double w, double x, double y, double z) {
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

std::array<double, 4> random_quaternion(std::mt19937& random) {
  std::normal_distribution<double> normal;
  std::array<double, 4> q{};
  double n = 0;
  for (double& c : q) c = normal(random), n += c * c;
  for (double& c : q) c /= std::sqrt(n);
  return q;
}

TEST(SphericalJoints, BallJointTopFollowsEulersEquationsAboutItsPivot) {
  namespace top = eomgen::models::ball_joint_top;
  auto p = top::Parameters<double>().values();
  double m = p[0], g = p[1];
  Matrix I;
  I << 0.02, 0.001, -0.002, 0.001, 0.025, 0.0015, -0.002, 0.0015, 0.04;
  Vector d = Vector(0.12, 0.03, 0.25) - Vector(0.1, 0, 0);  // centre from the pivot, body axes
  Matrix I_pivot = I + m * (d.squaredNorm() * Matrix::Identity() - d * d.transpose());
  std::mt19937 random(38);
  std::uniform_real_distribution<double> rate(-20, 20);
  for (int k = 0; k < 50; ++k) {
    auto q = random_quaternion(random);
    Vector w(rate(random), rate(random), rate(random));
    double x[7] = {q[0], q[1], q[2], q[3], w[0], w[1], w[2]}, xdot[7];
    top::rhs<double>(0.0, x, nullptr, p.data(), xdot);
    Vector gravity_moment = d.cross(rotation_of(q[0], q[1], q[2], q[3]).transpose() * Vector(0, 0, -m * g));
    Vector expected = I_pivot.ldlt().solve(gravity_moment - w.cross(I_pivot * w));
    Vector got(xdot[4], xdot[5], xdot[6]);
    EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << "state " << k << ": " << got.transpose() << " vs "
                                                                 << expected.transpose();
  }
}

TEST(SphericalJoints, FreeBodyHasEulersEquationsAndFallsWithGravity) {
  namespace body = eomgen::models::tumbling_body;
  static_assert(body::num_coordinates == 7 && body::num_velocities == 6, "position, quaternion; v, ω");
  auto p = body::Parameters<double>().values();
  double A = p[0], B = p[1], C = p[2], m = p[3], g = p[4];
  std::mt19937 random(39);
  std::uniform_real_distribution<double> any(-5, 5), length(0.2, 3);
  for (int k = 0; k < 50; ++k) {
    auto q = random_quaternion(random);
    double x[13], xdot[13], M[36];
    for (int i = 0; i < 3; ++i) x[i] = any(random), x[7 + i] = any(random), x[10 + i] = any(random);
    for (int i = 0; i < 4; ++i) x[3 + i] = q[std::size_t(i)];
    body::rhs<double>(0.0, x, nullptr, p.data(), xdot);
    body::mass_matrix<double>(0.0, x, p.data(), M);
    const double diagonal[6] = {m, m, m, A, B, C};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) EXPECT_NEAR(M[6 * i + j], i == j ? diagonal[i] : 0.0, 1e-14 * m) << i << ", " << j;
    EXPECT_NEAR(xdot[7], 0, 1e-14 * g);
    EXPECT_NEAR(xdot[8], 0, 1e-14 * g);
    EXPECT_NEAR(xdot[9], -g, 1e-14 * g);
    double wx = x[10], wy = x[11], wz = x[12];
    EXPECT_NEAR(xdot[10], (B - C) * wy * wz / A, 1e-13 * 25);
    EXPECT_NEAR(xdot[11], (C - A) * wz * wx / B, 1e-13 * 25);
    EXPECT_NEAR(xdot[12], (A - B) * wx * wy / C, 1e-13 * 25);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(xdot[i], x[7 + i]);
    // q' = ½ q ⊗ (0, ω): the rate of the rotation is R [ω]×
    Eigen::Quaterniond rate = Eigen::Quaterniond(x[3], x[4], x[5], x[6]) * Eigen::Quaterniond(0, wx, wy, wz);
    EXPECT_NEAR(xdot[3], rate.w() / 2, 1e-14 * 5);
    EXPECT_NEAR(xdot[4], rate.x() / 2, 1e-14 * 5);
    EXPECT_NEAR(xdot[5], rate.y() / 2, 1e-14 * 5);
    EXPECT_NEAR(xdot[6], rate.z() / 2, 1e-14 * 5);
    // a quaternion of another length is the same orientation: the accelerations do not change
    double s = length(random), scaled[13], scaled_dot[13];
    std::copy(x, x + 13, scaled);
    for (int i = 3; i < 7; ++i) scaled[i] *= s;
    body::rhs<double>(0.0, scaled, nullptr, p.data(), scaled_dot);
    for (int i = 7; i < 13; ++i) EXPECT_NEAR(scaled_dot[i], xdot[i], 1e-13 * 25);
  }
}

std::string diagnostics_of(const std::string& joint, const std::string& extra = "") {
  std::string text = "[model]\nname = \"ball\"\n" + extra + "\n[coordinates]\nqw = 1\nqx = 0\nqy = 0\nqz = 0\n\n"
                     "[[frames]]\nname = \"body\"\njoint = " + joint +
                     "\n\n[[rigid_bodies]]\nname = \"b\"\nframe = \"body\"\nmass = \"1\"\ncenter = [\"0\", \"0\", \"1\"]\n"
                     "inertia = [\"1\", \"1\", \"1\"]\n";
  return derive_model_text(text, "bad.toml").diagnostics.format();
}

TEST(SphericalJoints, MisusesAreLocated) {
  const std::string q = "quaternion = [\"qw\", \"qx\", \"qy\", \"qz\"]", w = "angular_velocity = [\"wx\", \"wy\", \"wz\"]";
  std::string fine = diagnostics_of("{ type = \"ball\", " + q + ", " + w + " }");
  EXPECT_EQ(fine, "") << fine;
  std::string no_quaternion = diagnostics_of("{ type = \"ball\", " + w + " }");
  EXPECT_NE(no_quaternion.find("a ball joint needs the coordinates of its quaternion"), std::string::npos) << no_quaternion;
  std::string three = diagnostics_of("{ type = \"ball\", quaternion = [\"qw\", \"qx\", \"qy\"], " + w + " }");
  EXPECT_NE(three.find("bad.toml:12:"), std::string::npos) << three;
  EXPECT_NE(three.find("expected 4 names"), std::string::npos) << three;
  std::string unknown = diagnostics_of("{ type = \"ball\", quaternion = [\"qw\", \"qx\", \"qy\", \"qv\"], " + w + " }");
  EXPECT_NE(unknown.find("'qv' is not a coordinate"), std::string::npos) << unknown;
  std::string no_w = diagnostics_of("{ type = \"ball\", " + q + " }");
  EXPECT_NE(no_w.find("needs names for its angular velocity"), std::string::npos) << no_w;
  std::string taken = diagnostics_of("{ type = \"ball\", " + q + ", angular_velocity = [\"qx\", \"wy\", \"wz\"] }");
  EXPECT_NE(taken.find("'qx' cannot name a velocity: the name is taken"), std::string::npos) << taken;
  std::string axis = diagnostics_of("{ type = \"ball\", " + q + ", " + w + ", axis = [\"0\", \"0\", \"1\"] }");
  EXPECT_NE(axis.find("a ball joint has no axis"), std::string::npos) << axis;
  std::string no_position = diagnostics_of("{ type = \"free\", " + q + ", " + w + " }");
  EXPECT_NE(no_position.find("a free joint needs the coordinates of its position"), std::string::npos) << no_position;
  std::string lagrange = diagnostics_of("{ type = \"ball\", " + q + ", " + w + " }", "method = \"lagrange2\"");
  EXPECT_NE(lagrange.find("bad.toml:3:"), std::string::npos) << lagrange;
  EXPECT_NE(lagrange.find("use method = \"appell\", or leave the method out"), std::string::npos) << lagrange;
  std::string expanded = diagnostics_of("{ type = \"ball\", " + q + ", " + w + " }", "kinematics = \"expanded\"");
  EXPECT_NE(expanded.find("bad.toml:3:14: error: model.kinematics: the key is retired"), std::string::npos) << expanded;
  std::string slerp = diagnostics_of("{ type = \"hinge\", " + q + " }");
  EXPECT_NE(slerp.find("'hinge' is not a joint type"), std::string::npos) << slerp;
  std::string omega = diagnostics_of("{ type = \"ball\", " + q + ", " + w + " }", "\n[energy]\nkinetic = \"0.01*wx^2\"");
  EXPECT_NE(omega.find("bad.toml:5:17: error: energy.kinetic: 'wx' is a ball or free joint's angular velocity, which the "
                       "kinetic energy cannot name"), std::string::npos) << omega;
  EXPECT_NE(omega.find("ω_x = 2(w der(x) − x der(w) − y der(z) + z der(y))"), std::string::npos) << omega;
  // written out in q, the quaternion's four rates would be the velocities: refused off a tree
  std::string shaken = diagnostics_of("{ type = \"ball\", " + q + ", " + w + " }",
                                      "\n[gravity]\nacceleration = [\"0\", \"0\", \"-9.81*(1 + sin(t))\"]");
  EXPECT_NE(shaken.find("bad.toml:14:"), std::string::npos) << shaken;
  EXPECT_NE(shaken.find("frame 'body' has a ball joint, which eomgen derives over a tree of joints only, and the model is "
                        "none: gravity changes with q or t"), std::string::npos) << shaken;
}

// A kinetic energy written in the quaternion's rates, Wᵀ(d/dt ∂T/∂q' − ∂T/∂q) with q'' = W s' + Ẇ s:
// - MuJoCo's armature a on a ball joint as eomgen import writes it, T = 2a|q'|² = ½ a|q|²|ω|², is at
//   unit q an inertia a·E about the pivot (its M_T Ẇ s = −a|ω|² q is normal to the quaternions'
//   sphere, which Wᵀ annihilates);
// - T = ½ c ω_x², ω_x = 2(w x' − x w' − y z' + z y'), is an inertia c about the body's x axis alone:
//   ∂T/∂q and Ẇ s both count.
// Either way M, f and the energy are those of the top whose inertia tensor has them added.
TEST(SphericalJoints, AKineticEnergyInTheQuaternionsRatesIsAnInertiaAboutThePivot) {
  const std::string top = read_file(model_path("ball_joint_top"));
  struct Case {
    std::string kinetic;
    std::vector<std::pair<std::string, std::string>> grown;  // the tensor's entries that grow by c
  };
  const Case cases[] = {{"2*c*(der(qw)^2 + der(qx)^2 + der(qy)^2 + der(qz)^2)",
                         {{"[[\"0.02\"", "[[\"0.02 + c\""}, {"\"0.025\"", "\"0.025 + c\""}, {"\"0.04\"]]", "\"0.04 + c\"]]"}}},
                        {"c/2*(2*(qw*der(qx) - qx*der(qw) - qy*der(qz) + qz*der(qy)))^2", {{"[[\"0.02\"", "[[\"0.02 + c\""}}}};
  const std::pair<std::string, std::string> parameter{"g = 9.81", "g = 9.81\nc = 0.013"};
  for (const Case& k : cases) {
    Equations rated = derive_text(edited(top, {{"[gravity]", "[energy]\nkinetic = \"" + k.kinetic + "\"\n\n[gravity]"}, parameter}));
    std::vector<std::pair<std::string, std::string>> grown = k.grown;
    grown.push_back(parameter);
    Equations inertia = derive_text(edited(top, grown));
    ASSERT_EQ(rated.symbols.velocities.size(), 3u) << k.kinetic;
    EXPECT_EQ(rated.symbols.velocities[0].get_name(), "wx") << k.kinetic;
    std::mt19937 random(40);
    std::uniform_real_distribution<double> rate(-20, 20);
    for (int n = 0; n < 20; ++n) {
      auto q = random_quaternion(random);
      std::map<std::string, double> state{{"m", 1.5}, {"g", 9.81}, {"c", 0.013}, {"qw", q[0]}, {"qx", q[1]}, {"qy", q[2]},
                                          {"qz", q[3]}, {"wx", rate(random)}, {"wy", rate(random)}, {"wz", rate(random)}};
      GiNaC::exmap at_rated = point_by_name(rated, state), at_inertia = point_by_name(inertia, state);
      for (unsigned i = 0; i < 3; ++i) {
        double f = value_at(inertia.forcing[i], at_inertia);
        EXPECT_NEAR(value_at(rated.forcing[i], at_rated), f, 1e-12 * std::max(1.0, std::abs(f))) << k.kinetic << ", state " << n << ", f" << i;
        for (unsigned j = 0; j < 3; ++j)
          EXPECT_NEAR(value_at(rated.mass_matrix(i, j), at_rated), value_at(inertia.mass_matrix(i, j), at_inertia), 1e-14)
              << k.kinetic << ", state " << n << ", M" << i << j;
      }
      double T = value_at(inertia.kinetic_energy, at_inertia);
      EXPECT_NEAR(value_at(rated.kinetic_energy, at_rated), T, 1e-12 * T) << k.kinetic << ", state " << n;
    }
  }
}

// T = ½ c q'_w² + the top's: a kinetic energy of (q, ω) whose M_T Ẇ s is not normal to the sphere,
// so that the projection's Ẇ s term counts; the energy E(q, ω) stays constant along the motion,
// dE/dt = ∂E/∂q·q' + ∂E/∂ω·ω' = 0, by central differences along (q', ω') at random states
TEST(SphericalJoints, AKineticEnergyInOneQuaternionRateKeepsTheEnergy) {
  Equations e = derive_text(edited(read_file(model_path("ball_joint_top")),
                                   {{"[gravity]", "[energy]\nkinetic = \"c/2*der(qw)^2\"\n\n[gravity]"}, {"g = 9.81", "g = 9.81\nc = 0.3"}}));
  const Symbols& s = e.symbols;
  ASSERT_EQ(s.velocities.size(), 3u);
  std::mt19937 random(41);
  std::uniform_real_distribution<double> rate(-5, 5);
  for (int n = 0; n < 10; ++n) {
    auto q = random_quaternion(random);
    std::map<std::string, double> state{{"m", 1.5}, {"g", 9.81}, {"c", 0.3}, {"qw", q[0]}, {"qx", q[1]}, {"qy", q[2]},
                                        {"qz", q[3]}, {"wx", rate(random)}, {"wy", rate(random)}, {"wz", rate(random)}};
    GiNaC::exmap at = point_by_name(e, state);
    std::vector<std::vector<double>> M(3, std::vector<double>(3));
    std::vector<double> f(3);
    for (unsigned i = 0; i < 3; ++i) {
      f[i] = value_at(e.forcing[i], at);
      for (unsigned j = 0; j < 3; ++j) M[i][j] = value_at(e.mass_matrix(i, j), at);
    }
    std::vector<double> dw = solved_linear_system(M, f);
    std::map<std::string, double> dstate;
    for (std::size_t k = 0; k < 4; ++k) dstate[s.coordinate_names[k]] = value_at(e.coordinate_rates[k], at);
    for (std::size_t k = 0; k < 3; ++k) dstate[s.velocities[k].get_name()] = dw[k];
    auto energy_at = [&](double h) {
      std::map<std::string, double> x = state;
      for (const auto& [name, d] : dstate) x[name] += h * d;
      GiNaC::exmap p = point_by_name(e, x);
      return value_at(e.kinetic_energy + e.potential_energy, p);
    };
    // the central difference's own error, about h² of the scale, is far below the tolerance; the
    // projection without its Ẇ s term misses by a tenth of the scale and more
    const double h = 1e-5;
    double power = (energy_at(h) - energy_at(-h)) / (2 * h), kinetic = value_at(e.kinetic_energy, at);
    double scale = kinetic * std::sqrt(dw[0] * dw[0] + dw[1] * dw[1] + dw[2] * dw[2]) /
                   std::sqrt(value_at(s.velocities[0] * s.velocities[0] + s.velocities[1] * s.velocities[1] + s.velocities[2] * s.velocities[2], at));
    EXPECT_LT(std::abs(power), 1e-7 * scale) << "state " << n << ": dE/dt " << power << " of a scale " << scale;
  }
}

TEST(SphericalJoints, QuaternionRatesFollowFromTheInitialAngularVelocity) {
  const std::string model = R"toml([model]
name = "spun"

[coordinates]
qw = 0.6
qx = 0.8
qy = 0
qz = RATE

[[frames]]
name = "body"
joint = { type = "ball", quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"], initial_angular_velocity = [1, 2, 3] }

[[rigid_bodies]]
name = "b"
frame = "body"
mass = "1"
center = ["0", "0", "0"]
inertia = ["1", "2", "3"]
)toml";
  auto with = [&](const std::string& qz) {
    std::string text = model;
    text.replace(text.find("RATE"), 4, qz);
    return text;
  };
  Equations e = derive_text(with("0"));
  ASSERT_EQ(e.symbols.initial_velocities.size(), 3u);
  EXPECT_NEAR(e.symbols.initial_velocities[0], 1, 1e-15);
  EXPECT_NEAR(e.symbols.initial_velocities[1], 2, 1e-15);
  EXPECT_NEAR(e.symbols.initial_velocities[2], 3, 1e-15);
  std::string rated = derive_model_text(with("{ initial = 0, rate = 1 }"), "bad.toml").diagnostics.format();
  EXPECT_NE(rated.find("coordinate 'qz' has an initial rate"), std::string::npos) << rated;
  std::string zero = derive_model_text(R"toml([model]
name = "none"
[coordinates]
qw = 0
qx = 0
qy = 0
qz = 0
[[frames]]
name = "body"
joint = { type = "ball", quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }
[[rigid_bodies]]
name = "b"
frame = "body"
mass = "1"
center = ["0", "0", "0"]
inertia = ["1", "2", "3"]
)toml", "bad.toml").diagnostics.format();
  EXPECT_NE(zero.find("the initial quaternion is zero"), std::string::npos) << zero;
}

// the turn's rotation vector θ·axis of a quaternion (w, v) of any length, the shorter way (θ ≤ π)
Vector turn_vector(const std::array<double, 4>& q) {
  Vector v(q[1], q[2], q[3]);
  double s = v.norm(), w = q[0] < 0 ? -q[0] : q[0];
  if (s == 0) return Vector::Zero();
  return (q[0] < 0 ? -1.0 : 1.0) * 2 * std::atan2(s, w) / s * v;
}

// the quaternion of a turn by angle about a unit axis, scaled by `length`
std::array<double, 4> turned_by(double angle, const Vector& axis, double length = 1) {
  Vector u = axis.normalized() * std::sin(angle / 2) * length;
  return {std::cos(angle / 2) * length, u[0], u[1], u[2]};
}

TEST(SphericalJoints, ATorsionSpringPullsByItsTurnsRotationVector) {
  namespace spring = eomgen::models::ball_spring_top;
  namespace top = eomgen::models::ball_joint_top;
  auto p = spring::Parameters<double>().values();
  auto p_top = top::Parameters<double>().values();
  double k = p[2];
  ASSERT_EQ(std::string(spring::parameter_names[2]), "k");
  Vector axis(0.3, -0.5, 0.8);
  // the turn at which atan_ratio changes from its series to its recurrence: |v|² = 0.3 w²
  double cut = 2 * std::atan(std::sqrt(0.3));
  std::vector<std::array<double, 4>> turns = {
      {1, 0, 0, 0},          turned_by(1e-9, axis),         turned_by(1e-4, axis, 3.0), turned_by(cut - 1e-9, axis),
      turned_by(cut + 1e-9, axis), turned_by(2.5, axis, 0.2), turned_by(M_PI - 1e-6, axis), {1e-12, 0.6, 0, 0.8},
      {-1e-12, 0.6, 0, 0.8},       turned_by(-2.0, axis, -1.5)};
  std::mt19937 random(5);
  for (int r = 0; r < 20; ++r) turns.push_back(random_quaternion(random));
  for (const auto& q : turns) {
    double x[7] = {q[0], q[1], q[2], q[3], 0.4, -1.1, 2.0}, f[3], f_top[3];
    spring::forcing<double>(0.0, x, nullptr, p.data(), f);
    top::forcing<double>(0.0, x, nullptr, p_top.data(), f_top);
    Vector pull = -k * turn_vector(q), got(f[0] - f_top[0], f[1] - f_top[1], f[2] - f_top[2]);
    double size = std::abs(f_top[0]) + std::abs(f_top[1]) + std::abs(f_top[2]) + k * pull.norm();
    EXPECT_LT((got - pull).norm(), 1e-14 * size) << q[0] << " " << q[1] << " " << q[2] << " " << q[3];
  }
  // at a half turn exactly (w = 0) the pull flips from −kπ·axis to kπ·axis: the spring takes the mean, 0,
  // where MuJoCo takes the side of w = +0
  double half[7] = {0, 0.6, 0, 0.8, 0.4, -1.1, 2.0}, f[3], f_top[3];
  spring::forcing<double>(0.0, half, nullptr, p.data(), f);
  top::forcing<double>(0.0, half, nullptr, p_top.data(), f_top);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], f_top[i], 1e-13) << i;
  // the Jacobian where the turn vanishes, next to it and at the cut: finite, and central differences'
  for (const auto& q : {std::array<double, 4>{1, 0, 0, 0}, turned_by(1e-3, axis), turned_by(cut, axis)}) {
    double x[7] = {q[0], q[1], q[2], q[3], 0.4, -1.1, 2.0}, J[49];
    spring::jacobian_state<double>(0.0, x, nullptr, p.data(), J);
    double largest = 0;
    for (double entry : J) largest = std::max(largest, std::abs(entry));
    for (int j = 0; j < 7; ++j) {
      double h = 1e-6, plus[7], minus[7], xp[7], xm[7];
      std::copy(x, x + 7, xp), std::copy(x, x + 7, xm);
      xp[j] += h, xm[j] -= h;
      spring::rhs<double>(0.0, xp, nullptr, p.data(), plus);
      spring::rhs<double>(0.0, xm, nullptr, p.data(), minus);
      for (int i = 0; i < 7; ++i) {
        ASSERT_TRUE(std::isfinite(J[i * 7 + j])) << "J[" << i << "][" << j << "] at q = " << q[0] << ", " << q[1];
        EXPECT_NEAR(J[i * 7 + j], (plus[i] - minus[i]) / (2 * h), 1e-7 * largest) << "J[" << i << "][" << j << "]";
      }
    }
  }
}

}  // namespace
}  // namespace eomgen::test
