// Which coordinates are angles (derive/angle_coordinates.hpp): those the equations take through a
// circular function of a whole multiple of them, whatever the method and however the kinematics
// are written; not a coordinate divided by a length inside sin, nor one that appears in no
// circular function at all.
#include <gtest/gtest.h>

#include "derive/angle_coordinates.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::vector<bool> angles_of(const std::string& model) { return angle_coordinates(derive_model(model)); }

TEST(AngleCoordinates, AreTheCoordinatesOfTurnsInEveryMethod) {
  EXPECT_EQ(angles_of("slider_crank"), (std::vector<bool>{true, true, false}));      // Lagrange I: phi, beta, x
  EXPECT_EQ(angles_of("cart_pendulum"), (std::vector<bool>{false, true}));           // x, theta
  EXPECT_EQ(angles_of("knife_edge"), (std::vector<bool>{false, false, true}));       // Appell: x, y, phi
  EXPECT_EQ(angles_of("pendulum_hamilton"), (std::vector<bool>{true}));              // Hamilton
  EXPECT_EQ(angles_of("measured_arm"), (std::vector<bool>{true, true, true}));       // frames, joint tree
  EXPECT_EQ(angles_of("oblique_tree"), (std::vector<bool>{true, true, true, false, true}));  // q4 slides
  EXPECT_EQ(angles_of("pendulum_cartesian"), (std::vector<bool>{false, false}));    // x, y on a rod
  EXPECT_EQ(angles_of("tumbling_body"), std::vector<bool>(7, false));                // position and quaternion
}

TEST(AngleCoordinates, AreNotCoordinatesScaledByALengthInsideACircularFunction) {
  Equations e = derive_text(R"toml([model]
name = "washboard"
[parameters]
m = 1.0
k = 2.0
w = 0.3
[coordinates]
x = { initial = 0.1, rate = 0.0 }
a = { initial = 0.2, rate = 0.0 }
[[particles]]
name = "bead"
mass = "m"
position = ["x", "cos(2*a + 1)", "0"]
[energy]
potential = "k*(1 - cos(x/w))"
)toml");
  EXPECT_EQ(angle_coordinates(e), (std::vector<bool>{false, true}));
}

}  // namespace
}  // namespace eomgen::test
