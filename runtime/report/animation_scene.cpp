// The scene around the drawn bodies (AnimationScene): what joins them, where to look from.
#include <algorithm>
#include <cmath>

#include "report/animation.hpp"

namespace eomgen::runtime {

namespace {

using Point = std::array<double, 3>;

double distance(const double* a, const double* b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

Point unit(Point v) {
  double n = std::hypot(v[0], v[1], v[2]);
  return n > 0 ? Point{v[0] / n, v[1] / n, v[2] / n} : v;
}

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// the bounding box of every drawn position over the run: lower and upper corners
std::array<Point, 2> bounds(const AnimationRecorder& r) {
  std::array<Point, 2> box{Point{INFINITY, INFINITY, INFINITY}, Point{-INFINITY, -INFINITY, -INFINITY}};
  for (std::size_t f = 0; f < r.frames(); ++f)
    for (std::size_t b = 0; b < r.model().num_drawn_bodies; ++b)
      for (int i = 0; i < 3; ++i)
        box[0][i] = std::min(box[0][i], r.pose(f, b)[i]), box[1][i] = std::max(box[1][i], r.pose(f, b)[i]);
  return box;
}

// A rod joins a body to its parent where their distance stays the same over the run (a link of
// the mechanism); to the ground point at the origin only for a body that moves about it so.
std::vector<std::array<int, 2>> constant_distance_rods(const AnimationRecorder& r, double scale) {
  static const double origin[3] = {0, 0, 0};
  std::vector<std::array<int, 2>> rods;
  const eomgen_model_abi& m = r.model();
  for (std::size_t b = 0; b < m.num_drawn_bodies; ++b) {
    int parent = m.drawn_body_parents[b];
    double lowest = INFINITY, highest = 0, travel = 0;
    for (std::size_t f = 0; f < r.frames(); ++f) {
      double d = distance(r.pose(f, b), parent < 0 ? origin : r.pose(f, std::size_t(parent)));
      lowest = std::min(lowest, d), highest = std::max(highest, d);
      travel = std::max(travel, distance(r.pose(f, b), r.pose(0, b)));
    }
    bool rigid = highest > 1e-9 * scale && highest - lowest <= 1e-6 * highest;
    if (rigid && (parent >= 0 || travel > 1e-6 * scale)) rods.push_back({int(b), parent});
  }
  return rods;
}

// the axis along which nothing moves and about which alone everything turns, or -1
int plane_normal(const AnimationRecorder& r, const std::array<Point, 2>& box, double scale) {
  for (int axis = 2; axis >= 0; --axis) {
    if (box[1][axis] - box[0][axis] > 1e-9 * scale) continue;
    bool about_axis = true;
    for (std::size_t f = 0; f < r.frames() && about_axis; ++f)
      for (std::size_t b = 0; b < r.model().num_drawn_bodies; ++b)
        about_axis = about_axis && std::abs(r.pose(f, b)[3 + 4 * axis] - 1) <= 1e-9;
    if (about_axis) return axis;
  }
  return -1;
}

// the lowest point of the run along `up`, from the centre, below the shapes
AnimationScene with_floor(const AnimationRecorder& r, AnimationScene s, double shape_size) {
  double lowest = INFINITY;
  for (std::size_t f = 0; f < r.frames(); ++f)
    for (std::size_t b = 0; b < r.model().num_drawn_bodies; ++b) {
      const double* p = r.pose(f, b);
      double height = 0;
      for (int i = 0; i < 3; ++i) height += (p[i] - s.center[std::size_t(i)]) * s.up[std::size_t(i)];
      lowest = std::min(lowest, height);
    }
  s.floor = std::isfinite(lowest) ? lowest - shape_size - 0.05 * s.radius : -s.radius;
  return s;
}

}  // namespace

AnimationScene animation_scene(const AnimationRecorder& r) {
  AnimationScene s;
  const eomgen_model_abi& m = r.model();
  m.gravity(r.parameters().data(), s.gravity.data());
  if (m.num_drawn_bodies == 0 || r.frames() == 0) return s;
  std::array<Point, 2> box = bounds(r);
  double extent = std::max({box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]});
  std::vector<double> shapes(18 * m.num_drawn_shapes);
  if (m.num_drawn_shapes) m.drawn_shapes(r.parameters().data(), shapes.data());
  double shape_size = 0;
  for (std::size_t k = 0; k < m.num_drawn_shapes; ++k)
    for (int i = 0; i < 6; ++i)
      if (std::isfinite(shapes[18 * k + std::size_t(i)])) shape_size = std::max(shape_size, std::abs(shapes[18 * k + std::size_t(i)]));
  double scale = std::max({extent, shape_size, std::hypot(box[0][0], box[0][1], box[0][2]) * 1e-9});
  if (!(scale > 0)) scale = 1;
  s.rods = constant_distance_rods(r, scale);
  for (const auto& rod : s.rods)
    if (rod[1] < 0)
      for (int i = 0; i < 3; ++i) box[0][i] = std::min(box[0][i], 0.0), box[1][i] = std::max(box[1][i], 0.0);
  for (int i = 0; i < 3; ++i) s.center[std::size_t(i)] = (box[0][i] + box[1][i]) / 2;
  s.radius = std::max(std::hypot(box[1][0] - box[0][0], box[1][1] - box[0][1], box[1][2] - box[0][2]) / 2 + shape_size,
                      scale * 0.5);
  s.extent = s.radius;
  // the bodies' own size: their largest distance from their centroid at any frame
  double own = 0;
  std::size_t nb = m.num_drawn_bodies;
  for (std::size_t f = 0; f < r.frames(); ++f) {
    Point c{0, 0, 0};
    for (std::size_t b = 0; b < nb; ++b)
      for (int i = 0; i < 3; ++i) c[std::size_t(i)] += r.pose(f, b)[i] / double(nb);
    for (std::size_t b = 0; b < nb; ++b) own = std::max(own, distance(r.pose(f, b), c.data()));
  }
  own += shape_size;
  if (own > 0 && 4 * own < s.radius) s.follow = true, s.radius = own;
  Point down = unit(s.gravity);
  int normal = plane_normal(r, box, scale);
  s.planar = normal >= 0;
  if (s.planar) {
    Point n{0, 0, 0};
    n[std::size_t(normal)] = 1;
    s.view = {-n[0], -n[1], -n[2]};
    Point in_plane{-down[0] * (1 - n[0]), -down[1] * (1 - n[1]), -down[2] * (1 - n[2])};
    // without gravity in the plane: y up in the xy plane, z up in the others
    Point level = normal == 2 ? Point{0, 1, 0} : Point{0, 0, 1};
    s.up = std::hypot(in_plane[0], in_plane[1], in_plane[2]) > 1e-3 ? unit(in_plane) : level;
    // from the side on which the plane's other axis points to the right (x right of y up, x right of z up)
    Point right = cross(s.view, s.up);
    if (right[0] + right[1] + right[2] < 0) s.view = n;
    return with_floor(r, s, shape_size);
  }
  s.up = std::hypot(down[0], down[1], down[2]) > 0 ? Point{-down[0], -down[1], -down[2]} : Point{0, 0, 1};
  int least = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(s.up[std::size_t(i)]) < std::abs(s.up[std::size_t(least)])) least = i;
  Point axis{0, 0, 0};
  axis[std::size_t(least)] = 1;
  Point e1 = unit(cross(s.up, axis)), e2 = cross(s.up, e1);
  Point eye = unit({0.8 * e1[0] - e2[0] + 0.5 * s.up[0], 0.8 * e1[1] - e2[1] + 0.5 * s.up[1], 0.8 * e1[2] - e2[2] + 0.5 * s.up[2]});
  s.view = {-eye[0], -eye[1], -eye[2]};
  return with_floor(r, s, shape_size);
}

}  // namespace eomgen::runtime
