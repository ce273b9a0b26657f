#include "symbolic_analysis/deformed_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace eomgen {

using GiNaC::ex;

namespace {

using Point3 = std::array<double, 3>;

double value_of(const ex& e, const GiNaC::exmap& at) {
  ex v = GiNaC::evalf(e.subs(at));
  return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real() ? GiNaC::ex_to<GiNaC::numeric>(v).to_double()
                                                                                     : NAN;
}

double spread(const std::vector<Point3>& points, int axis) {
  double low = INFINITY, high = -INFINITY;
  for (const Point3& p : points) low = std::min(low, p[axis]), high = std::max(high, p[axis]);
  return points.empty() ? 0 : high - low;
}

}  // namespace

DeformedShapes deformed_shapes(const Equations& e, const std::vector<double>& parameters, const std::vector<double>& inputs,
                               const std::vector<double>& state, const std::vector<std::vector<double>>& shapes) {
  DeformedShapes out;
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates();
  if (e.body_positions.empty()) {
    out.refusal = "the model has no particles or bodies to draw";
    return out;
  }
  GiNaC::exmap at{{s.time, 0}};
  for (std::size_t i = 0; i < s.parameters.size(); ++i) at[s.parameters[i]] = parameters[i];
  for (std::size_t i = 0; i < s.inputs.size(); ++i) at[s.inputs[i]] = inputs[i];
  for (std::size_t i = 0; i < n; ++i) at[s.coordinates[i]] = state[i];
  // r0 and the displacement (∂r/∂q) φ of each body in each mode
  std::vector<Point3> rest;
  std::vector<std::vector<Point3>> moved(shapes.size());
  for (const Equations::BodyPosition& b : e.body_positions) {
    Point3 r{}, zero{};
    for (int a = 0; a < 3; ++a) r[a] = value_of(b.position[a], at);
    rest.push_back(r);
    for (std::size_t m = 0; m < shapes.size(); ++m) {
      Point3 d = zero;
      for (int a = 0; a < 3; ++a)
        for (std::size_t k = 0; k < n; ++k) d[a] += value_of(b.position[a].diff(s.coordinates[k]), at) * shapes[m][k];
      moved[m].push_back(d);
    }
  }
  // how far the picture reaches along each axis: the bodies' spread, and each mode's motion relative to its largest
  std::array<double, 3> size{};
  for (int a = 0; a < 3; ++a) size[a] = spread(rest, a);
  for (const auto& displacement : moved) {
    double largest = 0;
    for (const Point3& d : displacement) largest = std::max({largest, std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
    for (const Point3& d : displacement)
      for (int a = 0; a < 3; ++a) size[a] += largest > 0 ? std::abs(d[a]) / largest : 0;
  }
  double extent = std::max({spread(rest, 0), spread(rest, 1), spread(rest, 2)});
  out.stations = !(extent > 1e-12);
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(), [&](int a, int b) { return size[a] > size[b] || (size[a] == size[b] && a < b); });
  const char* names[3] = {"x", "y", "z"};
  int h = std::min(axes[0], axes[1]), v = std::max(axes[0], axes[1]);
  if (out.stations) {
    out.horizontal = "station", out.vertical = std::string("displacement along ") + names[axes[0]];
    for (std::size_t b = 0; b < rest.size(); ++b) out.rest.push_back({double(b + 1), 0.0});
  } else {
    out.horizontal = names[h], out.vertical = names[v];
    for (const Point3& r : rest) out.rest.push_back({r[h], r[v]});
  }
  double picture = out.stations ? 1.0 : extent;
  for (const auto& displacement : moved) {
    double largest = 0;
    for (const Point3& d : displacement) largest = std::max(largest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    double a = largest > 0 ? picture / 3 / largest : 0;
    std::vector<std::array<double, 2>> points;
    for (std::size_t b = 0; b < rest.size(); ++b) {
      const Point3& d = displacement[b];
      points.push_back(out.stations ? std::array<double, 2>{double(b + 1), a * d[axes[0]]}
                                    : std::array<double, 2>{rest[b][h] + a * d[h], rest[b][v] + a * d[v]});
    }
    out.modes.push_back(points);
  }
  return out;
}

}  // namespace eomgen
