// rolls = { body, radius, axis }: the contact conditions eomgen forms for a thin disk
// against those written by hand. The disk whose centre is placed R*sin(theta) above the
// contact needs no contact condition, and its no-slip conditions are exactly
// der(x) + R*cos(psi)*der(phi) and der(y) + R*sin(psi)*der(phi); the disk with a free
// centre height z gets the contact condition z − R*sin(theta) = 0; a wheel whose axis
// tilts with the roll angle alone (the bicycle's rear wheel) gets |cos(phi)| exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "model/model.hpp"
#include "parse/model_file.hpp"
#include "pipeline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

Model build(const std::string& text) {
  Diagnostics d;
  ModelFile file = parse_model_text(text, "disk.toml", d);
  Model m = build_model(file, d);
  EXPECT_TRUE(d.empty()) << d.format();
  return m;
}

// the model's symbol called `name`: a parameter, a coordinate, or der(q) as d_q
ex symbol(const Model& m, const std::string& name) {
  const Symbols& s = m.symbols;
  for (std::size_t i = 0; i < s.parameters.size(); ++i)
    if (s.parameter_names[i] == name) return s.parameters[i];
  for (std::size_t i = 0; i < s.coordinates.size(); ++i) {
    if (s.coordinate_names[i] == name) return s.coordinates[i];
    if ("d_" + s.coordinate_names[i] == name) return s.velocities[i];
  }
  throw std::runtime_error("no symbol " + name);
}

// equal at 20 random points of every symbol (trigonometric identities included)
bool same(const ex& a, const ex& b) {
  GiNaC::exset symbols;
  for (const ex& e : {a, b})
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
      if (GiNaC::is_a<GiNaC::symbol>(*i)) symbols.insert(*i);
  for (int point = 0; point < 20; ++point) {
    GiNaC::exmap at;
    int k = 0;
    for (const ex& x : symbols) at[x] = GiNaC::numeric(std::sin(1.7 * point + 0.9 * ++k) + 1.2);
    double difference = value_at(a - b, at), size = std::max({1.0, std::abs(value_at(a, at)), std::abs(value_at(b, at))});
    if (std::abs(difference) > 1e-12 * size) return false;
  }
  return true;
}

TEST(RollingContact, TheDiskOfTheModelsFolderRollsAsWrittenByHand) {
  Model m = build(read_file(model_path("rolling_disk")));
  ASSERT_EQ(m.constraints.size(), 2u);
  EXPECT_FALSE(m.constraints[0].holonomic);
  EXPECT_EQ(m.constraints[0].name, "roll_slip_x");
  EXPECT_EQ(m.constraints[1].name, "roll_slip_y");
  ex R = symbol(m, "R"), psi = symbol(m, "psi"), d_x = symbol(m, "d_x"), d_y = symbol(m, "d_y"), d_phi = symbol(m, "d_phi");
  EXPECT_TRUE(same(m.constraints[0].expression, d_x + R * cos(psi) * d_phi)) << m.constraints[0].expression;
  EXPECT_TRUE(same(m.constraints[1].expression, d_y + R * sin(psi) * d_phi)) << m.constraints[1].expression;
}

const char* free_disk = R"toml([model]
name = "free_disk"
method = "appell"

[parameters]
m = 1.0
R = 0.1

[coordinates]
x = 0
y = 0
z = 0.0985
psi = 0.2
theta = 1.4
phi = 0

[[rigid_bodies]]
name = "disk"
mass = "m"
center = ["x", "y", "z"]
rotation = "euler313(psi, theta, phi)"
inertia = ["m*R^2/4", "m*R^2/4", "m*R^2/2"]

[[constraints]]
rolls = { body = "disk", radius = "R", axis = [0, 0, 2] }
)toml";

TEST(RollingContact, AFreeCentreGetsTheContactCondition) {
  Model m = build(free_disk);
  ASSERT_EQ(m.constraints.size(), 3u);
  EXPECT_TRUE(m.constraints[0].holonomic);
  EXPECT_EQ(m.constraints[0].name, "disk_contact");
  ex R = symbol(m, "R"), theta = symbol(m, "theta"), psi = symbol(m, "psi");
  EXPECT_TRUE(same(m.constraints[0].expression, symbol(m, "z") - R * sin(theta))) << m.constraints[0].expression;
  // the material point at the contact, c + ρ with ρ = R·(cos θ sin ψ, −cos θ cos ψ, −sin θ): its velocity
  // c' + ω × ρ, with ω = ψ' e_z + θ' e_line + φ' n (e_line = (cos ψ, sin ψ, 0), n = (sin ψ sin θ, −cos ψ sin θ, cos θ))
  ex d_psi = symbol(m, "d_psi"), d_theta = symbol(m, "d_theta"), d_phi = symbol(m, "d_phi");
  ex n[3] = {sin(psi) * sin(theta), -cos(psi) * sin(theta), cos(theta)};
  ex w[3] = {d_theta * cos(psi) + d_phi * n[0], d_theta * sin(psi) + d_phi * n[1], d_psi + d_phi * n[2]};
  ex rho[3] = {R * cos(theta) * sin(psi), -R * cos(theta) * cos(psi), -R * sin(theta)};
  ex slip_x = symbol(m, "d_x") + w[1] * rho[2] - w[2] * rho[1];
  ex slip_y = symbol(m, "d_y") + w[2] * rho[0] - w[0] * rho[2];
  EXPECT_TRUE(same(m.constraints[1].expression, slip_x)) << m.constraints[1].expression;
  EXPECT_TRUE(same(m.constraints[2].expression, slip_y)) << m.constraints[2].expression;
}

TEST(RollingContact, AWheelLeaningWithOneAngleHasAnExactContactHeight) {
  std::string text = R"toml([model]
name = "leaning_wheel"
method = "appell"

[parameters]
m = 2.0
r = 0.3

[coordinates]
x = 0
y = 0
psi = 0
phi = 0.1
h = 0.3
spin = 0

[[frames]]
name = "heading"
rotation = "rot_z(psi)"
origin = ["x", "y", "0"]

[[frames]]
name = "lean"
parent = "heading"
rotation = "rot_x(phi)"

[[rigid_bodies]]
name = "wheel"
mass = "m"
frame = "lean"
center = ["0", "0", "h"]
rotation = "rot_y(spin)"
inertia = ["m*r^2/4", "m*r^2/2", "m*r^2/4"]

[[constraints]]
name = "rear"
rolls = { body = "wheel", radius = "r", axis = [0, 1, 0] }
)toml";
  Model m = build(text);
  ASSERT_EQ(m.constraints.size(), 3u);
  EXPECT_EQ(m.constraints[0].name, "rear_contact");
  ex phi = symbol(m, "phi");
  EXPECT_TRUE(same(m.constraints[0].expression, symbol(m, "h") * cos(phi) - symbol(m, "r") * cos(phi)))
      << m.constraints[0].expression;
}

// a disk that lies flat has no lowest rim point (√(1 − n_z²) = 0): a located error, not a
// division by zero (the fuzzer found it through a lean frame whose angle was misnamed)
TEST(RollingContact, ADiskLyingFlatIsRefused) {
  std::string text = read_file(model_path("rolling_disk"));
  for (const std::string& flat : {std::string("rotation = \"rot_x(0)\""), std::string("rotation = \"rot_x(theta)\"")}) {
    std::string model = text;
    if (flat.find("theta") == std::string::npos) model.replace(model.find("rotation = \"rot_x(theta)\""), 25, flat);
    else model.replace(model.find("theta = { initial = 1.4"), 23, "theta = { initial = 0.0");
    Diagnostics d;
    ModelFile file = parse_model_text(model, "disk.toml", d);
    build_model(file, d);
    EXPECT_NE(d.format().find("rolls.axis: the disk lies flat at the initial state"), std::string::npos) << flat << "\n" << d.format();
  }
}

// a disk axis tilted in the body frame: the derivation ends (with its equations or a located
// error); printing a power whose base leads with a minus either way had recursed without end
TEST(RollingContact, ATiltedAxisEndsTheDerivation) {
  std::string model = read_file(model_path("rolling_disk"));
  model.replace(model.find("axis = [0, 0, 1]"), 16, "axis = [5, 0, 1]");
  Derivation d = derive_model_text(model, "disk.toml");
  EXPECT_TRUE(d.equations.has_value() || !d.diagnostics.empty());
}

}  // namespace
}  // namespace eomgen::test
