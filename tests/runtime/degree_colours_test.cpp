// The stability map's colour scale (report/degree_colours.hpp) on the degrees of a damped
// oscillator, q'' + d q' + k q = 0, mapped over d and k on logarithmic axes of six decades:
// largest real part −d/2 + Re √(d²/4 − k).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "report/degree_colours.hpp"

namespace eomgen::test {
namespace {

std::vector<double> oscillator_degrees(double low, double high, double scale) {
  std::vector<double> degrees;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      double d = low * std::pow(high / low, i / 39.0), k = low * std::pow(high / low, j / 39.0);
      degrees.push_back(scale * (-d / 2 + std::sqrt(std::complex<double>(d * d / 4 - k)).real()));
    }
  return degrees;
}

// Over six decades the small degrees were white beside the largest (1e-6 of the scale, linear):
// now each decade has its share of the colours, the same at every time scale s (degrees times s,
// from 1e-20 to 1e20; the old scale's floor of 1e-12 had left a slow system's map white).
TEST(DegreeColours, AMapOverDecadesShowsItsSmallDegreesAtEveryScale) {
  std::vector<double> at_unit_scale = oscillator_degrees(1e-6, 1.0, 1.0);
  runtime::DegreeColours unit = runtime::degree_colours(at_unit_scale);
  ASSERT_GT(unit.knee, 0);
  double smallest = INFINITY;  // −d/2 = −5e-7 at the least damping
  for (double d : at_unit_scale) smallest = std::min(smallest, std::abs(d));
  EXPECT_NEAR(smallest, 5e-7, 1e-12);
  EXPECT_GT(std::abs(unit.colour(-smallest)) / unit.range(), 0.01);
  EXPECT_LT(std::abs(unit.colour(-smallest)) / unit.range(), 0.2);
  for (double s : {1e-20, 1e-12, 1e-6, 1.0, 1e6, 1e12, 1e20}) {
    std::vector<double> degrees = oscillator_degrees(1e-6, 1.0, s);
    runtime::DegreeColours scaled = runtime::degree_colours(degrees);
    EXPECT_NEAR(scaled.knee / (s * unit.knee), 1, 1e-12) << "s = " << s;
    EXPECT_NEAR(scaled.largest / (s * unit.largest), 1, 1e-12) << "s = " << s;
    for (double d : degrees) {
      EXPECT_NEAR(scaled.colour(d) / scaled.range(), unit.colour(d / s) / unit.range(), 1e-12) << "s = " << s;
      EXPECT_EQ(scaled.colour(-d), -scaled.colour(d)) << "the zero contour stays where the degree changes sign";
    }
  }
  EXPECT_EQ(unit.colour(0), 0);
  EXPECT_TRUE(std::isnan(unit.colour(NAN)));
  EXPECT_NE(unit.tics().find("'0' 0, '0.1' "), std::string::npos) << unit.tics();
  EXPECT_NE(unit.tics().find("'-1e-06' "), std::string::npos) << unit.tics();
}

// Within two decades the scale stays linear, ±(the largest |degree|), at every time scale.
TEST(DegreeColours, AMapWithinTwoDecadesIsColouredLinearly) {
  for (double s : {1e-20, 1e-12, 1.0, 1e12, 1e20}) {
    runtime::DegreeColours c = runtime::degree_colours(oscillator_degrees(0.1, 1.0, s));
    EXPECT_EQ(c.knee, 0) << "s = " << s;
    EXPECT_NEAR(c.range() / (s * 0.5), 1, 1e-12) << "s = " << s << ": the largest |degree| is d/2 at d = 1";
    EXPECT_EQ(c.colour(-0.3 * s), -0.3 * s);
    EXPECT_EQ(c.tics(), "");
  }
  EXPECT_EQ(runtime::degree_colours({0.0, NAN, 0.0}).range(), 1) << "nothing but zeros: white, whatever the range";
}

}  // namespace
}  // namespace eomgen::test
