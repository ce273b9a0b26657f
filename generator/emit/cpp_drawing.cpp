#include "emit/cpp_drawing.hpp"

#include <fmt/format.h>

#include "emit/cpp_body_writer.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

template <class List, class Text>
std::string joined(const List& list, Text text) {
  std::string out;
  for (const auto& item : list) out += (out.empty() ? "" : ", ") + text(item);
  return out;
}

std::string declarations(const Equations& e) {
  std::vector<std::string> names;
  std::vector<int> parents, kinds, shape_bodies, shape_types;
  for (std::size_t i = 0; i < e.drawing.size(); ++i) {
    const DrawnBody& d = e.drawing[i];
    names.push_back(d.name), parents.push_back(d.parent), kinds.push_back(int(d.kind));
    for (const Shape& s : d.shapes) shape_bodies.push_back(int(i)), shape_types.push_back(int(s.type));
  }
  auto integer = [](int v) { return std::to_string(v); };
  return fmt::format(
      "/// What `eomgen animate` draws: the frames, particles, rigid bodies and points (kinds 0, 1, 2, 3),\n"
      "/// each joined to its parent (-1: the ground), and the shapes on them (types: 0 sphere, 1 box,\n"
      "/// 2 capsule, 3 cylinder, 4 ellipsoid).\n"
      "inline constexpr std::size_t num_drawn_bodies = {};\n"
      "inline constexpr std::array<const char*, num_drawn_bodies> drawn_body_names{{{{{}}}}};\n"
      "inline constexpr std::array<int, num_drawn_bodies> drawn_body_kinds{{{{{}}}}};\n"
      "inline constexpr std::array<int, num_drawn_bodies> drawn_body_parents{{{{{}}}}};\n"
      "inline constexpr std::size_t num_drawn_shapes = {};\n"
      "inline constexpr std::array<int, num_drawn_shapes> drawn_shape_bodies{{{{{}}}}};\n"
      "inline constexpr std::array<int, num_drawn_shapes> drawn_shape_types{{{{{}}}}};\n\n",
      names.size(), quoted_list(names), joined(kinds, integer), joined(parents, integer), shape_bodies.size(),
      joined(shape_bodies, integer), joined(shape_types, integer));
}

std::string poses_function(const Equations& e) {
  BodyWriter w(e);
  std::vector<ex> values;
  for (const DrawnBody& d : e.drawing) {
    for (const ex& x : d.position) values.push_back(x);
    for (unsigned i = 0; i < 9; ++i) values.push_back(d.rotation.op(i));
  }
  w.assign(values, [](std::size_t i, const std::string& code) { return fmt::format("out[{}] = {};", i, code); });
  return function("/// Each drawn body's position (inertial) and rotation R (its axes to inertial ones, row by row).\n"
                  "/// x: num_states; p: num_parameters; out: 12 per drawn body.\n",
                  "void body_poses(T t, const T* x, const T* p, T* out)", w.finish("(void)t; (void)x; (void)p; (void)out;"));
}

std::string shapes_function(const Equations& e) {
  BodyWriter w(e);
  std::vector<ex> values;
  for (const DrawnBody& d : e.drawing)
    for (const Shape& s : d.shapes) {
      for (const Vector3* v : {&s.size, &s.offset, &s.axis})
        for (const ex& x : *v) values.push_back(x);
      for (unsigned i = 0; i < 9; ++i) values.push_back(s.rotation.op(i));
    }
  w.assign(values, [](std::size_t i, const std::string& code) { return fmt::format("out[{}] = {};", i, code); });
  return function("/// Each drawn shape's sizes (sphere: radius; box: sides; capsule, cylinder: radius, length; ellipsoid:\n"
                  "/// radii; 0: the viewer's choice), centre, axis (a capsule's or cylinder's) and rotation (the shape's\n"
                  "/// axes in its body's, row by row, applied after the axis), in its body's axes. p: num_parameters;\n"
                  "/// out: 18 per shape.\n",
                  "void drawn_shapes(const T* p, T* out)", w.finish("(void)p; (void)out;"));
}

std::string gravity_function(const Equations& e) {
  BodyWriter w(e);
  w.assign({e.gravity[0], e.gravity[1], e.gravity[2]},
           [](std::size_t i, const std::string& code) { return fmt::format("g[{}] = {};", i, code); });
  return function("/// The acceleration of gravity, inertial components. p: num_parameters; g: 3.\n",
                  "void gravity(const T* p, T* g)", w.finish("(void)p;"));
}

}  // namespace

std::string drawing_functions(const Equations& e) {
  return declarations(e) + poses_function(e) + shapes_function(e) + gravity_function(e);
}

}  // namespace eomgen
