// The bodies' ∂τ/∂q and ∂τ/∂s in closed form (generator/spatial/joint_tree_derivatives.hpp) on a
// floating base: a free torso (position, quaternion, angular velocity), a ball joint through an
// offset anchor below it, a hinge about an oblique axis and a slide on that, a fixed frame, and
// springs and a damper (the applied part, which the closed form leaves out). At random states,
// with the quaternion off its unit length, each entry against central differences of the bodies'
// τ = inverse_dynamics − applied_inverse_dynamics, evaluated from the recursion's own definitions.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include <fmt/format.h>

#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* floating = R"toml([model]
name = "floating"

[parameters]
m = 2.1
g = 9.81

[gravity]
acceleration = ["0", "0", "-g"]

[coordinates]
x = 0.1
y = -0.2
z = 0.5
qw = 1
qx = 0
qy = 0
qz = 0
pw = 1
px = 0
py = 0
pz = 0
h = 0.3
s = 0.05

[[frames]]
name = "torso"
joint = { type = "free", position = ["x", "y", "z"], quaternion = ["qw", "qx", "qy", "qz"], angular_velocity = ["wx", "wy", "wz"] }

[[frames]]
name = "shoulder"
parent = "torso"
origin = ["0.2", "0.1", "0"]
joint = { type = "ball", anchor = ["0.02", "0", "-0.03"], quaternion = ["pw", "px", "py", "pz"], angular_velocity = ["ox", "oy", "oz"] }

[[frames]]
name = "elbow"
parent = "shoulder"
origin = ["0", "0", "-0.3"]
rotation = "rot_x(0.4)"
joint = { type = "revolute", axis = ["1", "2", "2"], anchor = ["0.01", "0.02", "0"], coordinate = "h" }

[[frames]]
name = "mount"
parent = "elbow"
origin = ["0.05", "0", "-0.1"]
joint = { type = "fixed" }

[[frames]]
name = "slider"
parent = "mount"
joint = { type = "prismatic", axis = ["0", "3", "4"], coordinate = "s" }

[[rigid_bodies]]
name = "body"
mass = "m"
frame = "torso"
center = ["0.01", "-0.02", "0.03"]
inertia = [["0.08", "0.004", "-0.002"], ["0.004", "0.11", "0.003"], ["-0.002", "0.003", "0.07"]]

[[rigid_bodies]]
name = "upper"
mass = "0.6"
frame = "shoulder"
center = ["0", "0.01", "-0.15"]
inertia = ["0.006", "0.005", "0.002"]
rotation = "rot_y(0.3)"

[[rigid_bodies]]
name = "lower"
mass = "0.4"
frame = "elbow"
center = ["0.02", "0", "-0.08"]
inertia = [["0.003", "0.0002", "-0.0001"], ["0.0002", "0.0025", "0.0003"], ["-0.0001", "0.0003", "0.002"]]

[[particles]]
name = "bolt"
mass = "0.1"
frame = "mount"
position = ["0", "0.01", "0"]

[[rigid_bodies]]
name = "carriage"
mass = "0.3"
frame = "slider"
center = ["0.01", "0", "0"]
inertia = ["0.0004", "0.0005", "0.0006"]

[energy]
potential = "5*h^2 + 40*s^2"
dissipation = "0.2*der(h)^2/2"
)toml";

TEST(JointTreeDerivatives, FloatingBaseAgreesWithCentralDifferences) {
  Equations e = derive_text(floating);
  ASSERT_TRUE(e.has_bodies_gradient());
  const Symbols& sym = e.symbols;
  std::size_t nq = sym.num_coordinates(), n = e.num_velocities();
  ASSERT_EQ(nq, 13u);
  ASSERT_EQ(n, 11u);
  ASSERT_EQ(e.bodies_gradient_coordinates.cols(), nq);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> value(-1, 1), scale(0.6, 1.8);
  for (int point = 0; point < 2; ++point) {
    std::map<std::string, double> values;
    for (const std::string& p : sym.parameter_names) values[p] = scale(random) * (p == "g" ? 9.81 : 1.0);
    for (const std::string& q : sym.coordinate_names) values[q] = value(random);
    values["qw"] += 1.5, values["pw"] -= 1.5;  // |q| ≠ 1
    for (const GiNaC::realsymbol& v : sym.velocities) values[v.get_name()] = 2 * value(random);
    for (std::size_t k = 0; k < n; ++k) values[fmt::format("ddq{}", k)] = 3 * value(random);
    // the bodies' τ at a point: each point evaluates every intermediate once
    auto bodies_tau = [&](const std::map<std::string, double>& values_at) {
      GiNaC::exmap p = point_by_name(e, values_at);
      std::vector<double> tau(n);
      for (std::size_t i = 0; i < n; ++i) tau[i] = value_at(e.inverse_dynamics[i], p) - value_at(e.applied_inverse_dynamics[i], p);
      return tau;
    };
    GiNaC::exmap at = point_by_name(e, values);
    auto check = [&](const std::string& name, auto closed) {
      std::map<std::string, double> plus = values, minus = values;
      double h = 1e-6 * std::max(1.0, std::abs(values.at(name)));
      plus[name] += h, minus[name] -= h;
      std::vector<double> up = bodies_tau(plus), down = bodies_tau(minus);
      for (std::size_t i = 0; i < n; ++i) {
        double difference = (up[i] - down[i]) / (2 * h), exact = value_at(closed(unsigned(i)), at);
        EXPECT_NEAR(exact, difference, 1e-7 * std::max(1.0, std::abs(difference)))
            << "d tau_" << i << " / d " << name << " at point " << point;
      }
    };
    for (unsigned c = 0; c < nq; ++c)
      check(sym.coordinate_names[c], [&](unsigned i) { return e.bodies_gradient_coordinates(i, c); });
    for (unsigned c = 0; c < n; ++c)
      check(sym.velocities[c].get_name(), [&](unsigned i) { return e.bodies_gradient_velocities(i, c); });
  }
}

}  // namespace
}  // namespace eomgen::test
