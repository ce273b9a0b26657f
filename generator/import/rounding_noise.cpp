#include "import/rounding_noise.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace eomgen {

namespace {

constexpr double units_of_rounding = 8;

// each component at most `units_of_rounding` of rounding of `scale` set to zero, counted
template <std::size_t n>
void clean(std::array<double, n>& x, double scale, RoundingNoise& noise) {
  for (double& c : x) {
    if (c == 0 || std::abs(c) > units_of_rounding * DBL_EPSILON * scale) continue;
    noise.largest = std::max(noise.largest, std::abs(c) / (DBL_EPSILON * scale));
    c = 0;
    ++noise.numbers;
  }
}

template <std::size_t n>
double length_of(const std::array<double, n>& x) {
  double sum = 0;
  for (double c : x) sum += c * c;
  return std::sqrt(sum);
}

template <std::size_t n>
void clean_direction(std::array<double, n>& x, RoundingNoise& noise) {
  clean(x, length_of(x), noise);
}

// the largest offset, centre of mass or anchor of the robot, in its length unit
double size_of(const Robot& r) {
  double size = 0;
  auto widen = [&](const Triple& x) {
    for (double c : x) size = std::max(size, std::abs(c));
  };
  for (const RobotBody& b : r.bodies) {
    widen(b.position), widen(b.center);
    for (const RobotJoint& j : b.joints) widen(j.anchor);
  }
  for (const RobotSite& s : r.sites) widen(s.position);
  return size;
}

}  // namespace

RoundingNoise without_rounding_noise(Robot& robot) {
  RoundingNoise noise;
  double size = size_of(robot);
  for (RobotBody& b : robot.bodies) {
    clean(b.position, size, noise);
    clean(b.center, size, noise);
    clean_direction(b.orientation, noise);
    clean_direction(b.inertia_axes, noise);
    clean(b.principal_inertia, b.mass * size * size, noise);
    for (RobotJoint& j : b.joints) {
      clean_direction(j.axis, noise);
      clean(j.anchor, size, noise);
    }
  }
  for (RobotSite& s : robot.sites) clean(s.position, size, noise);
  for (RobotLoop& l : robot.loops) clean(l.anchor1, size, noise), clean(l.anchor2, size, noise);
  return noise;
}

}  // namespace eomgen
