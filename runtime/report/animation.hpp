/// @file An animation of a run (`eomgen animate`, `simulate --animate`): the poses of the model's
/// drawn bodies, computed by the generated code's body_poses at the run's output times, and the
/// one self-contained HTML page that plays them with three.js.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace eomgen::runtime {

/// The drawn bodies' poses along a run, recorded as its rows come (SimulationSettings::stream).
/// At most `max_frames` are kept: beyond that every other frame is dropped and the interval doubles.
class AnimationRecorder {
 public:
  AnimationRecorder(const eomgen_model_abi& model, std::vector<double> parameters, std::size_t max_frames = 6000);
  void take(const Trajectory& rows);
  const eomgen_model_abi& model() const { return model_; }
  const std::vector<double>& parameters() const { return parameters_; }
  std::size_t frames() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }
  /// Body b at frame f: its position (3) and rotation R (9, row by row), as body_poses writes them.
  const double* pose(std::size_t f, std::size_t b) const { return &poses_[(f * bodies_ + b) * 12]; }

 private:
  void thin();
  const eomgen_model_abi& model_;
  std::vector<double> parameters_;
  std::size_t bodies_, max_frames_, every_ = 1, seen_ = 0;
  std::vector<double> times_, poses_;
};

/// What the page shows besides the bodies.
struct AnimationSettings {
  std::string title;
  std::vector<std::string> trace;  // bodies or points whose path is drawn
  bool axes = false;               // each body's axes
};

/// The scene around the bodies, from the recorded poses: rods where a body keeps its distance
/// from its parent (or the ground point at the origin), the centre and radius of what moves, and
/// a view along the normal of a planar motion (else oblique), with gravity pointing down.
struct AnimationScene {
  std::vector<std::array<int, 2>> rods;  // body, parent (-1: the origin)
  std::array<double, 3> center{}, view{}, up{}, gravity{};
  double radius = 1;
  bool planar = false;
  /// A model that travels far beyond its own size (a bicycle riding off, a body falling): the view
  /// follows the bodies' centroid, `radius` is their own size and `extent` the whole run's
  bool follow = false;
  double extent = 1;
  double floor = -1;  // the lowest point along `up` over the run, from the centre
};
AnimationScene animation_scene(const AnimationRecorder& recorder);

/// The unit quaternion (w, x, y, z) of a rotation matrix (row by row), by Shepperd's method.
std::array<double, 4> rotation_quaternion(const double* R);

/// The HTML page: three.js (from Debian's libjs-three), the poses and the player, inline.
/// Empty with `error` set when it cannot be made (a trace names no drawn body, a pose is not
/// finite, three.js is missing, the model draws nothing).
std::string animation_page(const AnimationRecorder& recorder, const AnimationSettings& settings, std::string& error);

}  // namespace eomgen::runtime
