// [definitions]: named expressions used anywhere an expression is allowed. The double
// pendulum written with definitions derives to the same equations as written out (by
// `eomgen diff`); a definition of parameters alone follows --set like a parameter; and
// each misuse is located.
#include <gtest/gtest.h>

#include <fstream>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const char* with_definitions = R"toml([model]
name = "swing2"
title = "Double pendulum with definitions"

[parameters]
m1 = 1.0
m2 = 0.5
l1 = 1.0
l2 = 0.7
g = 9.81

[coordinates]
phi1 = 0.5
phi2 = 0.0

[definitions]
x1 = "l1*sin(phi1)"
y1 = "-l1*cos(phi1)"
x2 = "x1 + l2*sin(phi2)"
y2 = "y1 - l2*cos(phi2)"
rod_inertia = "m2*l2^2/12"

[[particles]]
name = "bob1"
mass = "m1"
position = ["x1", "y1", "0"]

[[particles]]
name = "bob2"
mass = "m2"
position = ["x2", "y2", "0"]

[energy]
kinetic = "rod_inertia*der(phi2)^2/2"

[gravity]
acceleration = ["0", "-g", "0"]

[outputs]
tip_height = "y2"
)toml";

const char* written_out = R"toml([model]
name = "swing2"
title = "Double pendulum with definitions"

[parameters]
m1 = 1.0
m2 = 0.5
l1 = 1.0
l2 = 0.7
g = 9.81

[coordinates]
phi1 = 0.5
phi2 = 0.0

[[particles]]
name = "bob1"
mass = "m1"
position = ["l1*sin(phi1)", "-l1*cos(phi1)", "0"]

[[particles]]
name = "bob2"
mass = "m2"
position = ["l1*sin(phi1) + l2*sin(phi2)", "-l1*cos(phi1) - l2*cos(phi2)", "0"]

[energy]
kinetic = "m2*l2^2/12*der(phi2)^2/2"

[gravity]
acceleration = ["0", "-g", "0"]

[outputs]
tip_height = "-l1*cos(phi1) - l2*cos(phi2)"
)toml";

std::string write(const std::string& name, const std::string& text) {
  std::string path = temporary_directory() + "/" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

TEST(Definitions, DeriveToTheSameEquationsAsTheModelWrittenOut) {
  CommandOutput r = run_eomgen("diff '" + write("written_out", written_out) + "' '" + write("defined", with_definitions) + "'");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("identical"), std::string::npos) << r.out;
}

TEST(Definitions, ADefinitionOfParametersFollowsSet) {
  // rod_inertia = m2 l2^2/12: with l2 set to 1.4 both files give the same natural frequencies
  auto frequencies = [](const std::string& path) {
    JsonValue v = run_json("linear '" + path + "' --set l2=1.4 --set m2=2");
    std::vector<double> out;
    if (const JsonValue* modes = v.find("modes"))
      for (const JsonValue& m : modes->items) out.push_back(at(m, "frequency_rad_s"));
    return out;
  };
  std::vector<double> defined = frequencies(write("defined", with_definitions)), out = frequencies(write("out", written_out));
  ASSERT_EQ(defined.size(), 2u);
  ASSERT_EQ(out.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(defined[k], out[k], 1e-12 * out[k]) << "mode " << k;
}

TEST(Definitions, MisusesAreLocated) {
  std::string text = with_definitions;
  auto variant = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return run_eomgen("derive '" + write("broken", t) + "'");
  };
  CommandOutput moving_mass = variant("mass = \"m2\"", "mass = \"x1\"");
  EXPECT_EQ(moving_mass.status, 2);
  EXPECT_NE(moving_mass.err.find("broken.toml:30:9: error: particles[1].mass: definition 'x1' depends on the coordinate phi1, "
                                 "which a mass may not"),
            std::string::npos)
      << moving_mass.err;
  CommandOutput later = variant("x1 = \"l1*sin(phi1)\"", "x0 = \"x1\"\nx1 = \"l1*sin(phi1)\"");
  EXPECT_NE(later.err.find("definitions.x0: 'x1' is not defined yet: [definitions] are read from the top"), std::string::npos) << "only earlier definitions\n" << later.err;
  CommandOutput twice = variant("rod_inertia =", "m1 =");
  EXPECT_NE(twice.err.find("symbol 'm1' is defined twice: as a parameter (line 6) and as a definition"), std::string::npos)
      << twice.err;
  CommandOutput velocity = variant("[outputs]\n", "[outputs]\nspeed = \"der(x1)\"\n");
  EXPECT_NE(velocity.err.find("der() of definition 'x1': only coordinates have velocities"), std::string::npos) << velocity.err;
}

}  // namespace
}  // namespace eomgen::test
