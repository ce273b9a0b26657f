#include <algorithm>
#include <cmath>

#include "report/animation.hpp"

namespace eomgen::runtime {

AnimationRecorder::AnimationRecorder(const eomgen_model_abi& model, std::vector<double> parameters, std::size_t max_frames)
    : model_(model), parameters_(std::move(parameters)), bodies_(model.num_drawn_bodies), max_frames_(max_frames) {}

void AnimationRecorder::take(const Trajectory& rows) {
  std::vector<double> pose(12 * bodies_);
  for (std::size_t k = 0; k < rows.times.size(); ++k, ++seen_) {
    if (seen_ % every_ != 0) continue;
    if (bodies_) model_.body_poses(rows.times[k], rows.states[k].data(), parameters_.data(), pose.data());
    times_.push_back(rows.times[k]);
    poses_.insert(poses_.end(), pose.begin(), pose.end());
    if (times_.size() >= 2 * max_frames_) thin();
  }
}

// every other frame goes, and from now on every other row is recorded
void AnimationRecorder::thin() {
  std::size_t kept = 0, width = 12 * bodies_;
  for (std::size_t f = 0; f < times_.size(); f += 2, ++kept) {
    times_[kept] = times_[f];
    std::copy(poses_.begin() + std::ptrdiff_t(f * width), poses_.begin() + std::ptrdiff_t((f + 1) * width),
              poses_.begin() + std::ptrdiff_t(kept * width));
  }
  times_.resize(kept), poses_.resize(kept * width);
  every_ *= 2;
}

std::array<double, 4> rotation_quaternion(const double* R) {
  auto at = [R](int i, int j) { return R[3 * i + j]; };
  double trace = at(0, 0) + at(1, 1) + at(2, 2);
  std::array<double, 4> q;
  // Shepperd: divide by the largest of 4w², 4x², 4y², 4z², which is at least 1 for a rotation
  if (trace >= at(0, 0) && trace >= at(1, 1) && trace >= at(2, 2)) {
    double s = 2 * std::sqrt(1 + trace);
    q = {s / 4, (at(2, 1) - at(1, 2)) / s, (at(0, 2) - at(2, 0)) / s, (at(1, 0) - at(0, 1)) / s};
  } else if (at(0, 0) >= at(1, 1) && at(0, 0) >= at(2, 2)) {
    double s = 2 * std::sqrt(1 + at(0, 0) - at(1, 1) - at(2, 2));
    q = {(at(2, 1) - at(1, 2)) / s, s / 4, (at(0, 1) + at(1, 0)) / s, (at(0, 2) + at(2, 0)) / s};
  } else if (at(1, 1) >= at(2, 2)) {
    double s = 2 * std::sqrt(1 - at(0, 0) + at(1, 1) - at(2, 2));
    q = {(at(0, 2) - at(2, 0)) / s, (at(0, 1) + at(1, 0)) / s, s / 4, (at(1, 2) + at(2, 1)) / s};
  } else {
    double s = 2 * std::sqrt(1 - at(0, 0) - at(1, 1) + at(2, 2));
    q = {(at(1, 0) - at(0, 1)) / s, (at(0, 2) + at(2, 0)) / s, (at(1, 2) + at(2, 1)) / s, s / 4};
  }
  double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= norm;
  return q;
}

}  // namespace eomgen::runtime
