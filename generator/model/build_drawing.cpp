// What `eomgen animate` draws: every frame, particle, rigid body and point, placed as the model
// places it, with its shapes (or a particle's sphere, a rigid body's box of inertia).
#include <fmt/format.h>

#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

GiNaC::matrix identity() { return GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)); }

Shape::Type shape_type(const std::string& name) {
  if (name == "box") return Shape::Type::box;
  if (name == "ellipsoid") return Shape::Type::ellipsoid;
  if (name == "capsule") return Shape::Type::capsule;
  if (name == "cylinder") return Shape::Type::cylinder;
  return Shape::Type::sphere;
}

}  // namespace

std::vector<Shape> ModelBuilder::shapes(const std::vector<ShapeEntry>& entries) {
  std::vector<Shape> out;
  for (const ShapeEntry& e : entries) {
    Shape s;
    s.type = shape_type(e.type);
    for (std::size_t i = 0; i < e.size.size() && i < 3; ++i)
      if (auto v = parse(e.size[i], allow_parameters, "a shape's size")) s.size[i] = *v;
    if (!e.offset.empty()) s.offset = vector(e.offset, allow_parameters, "a shape's offset");
    if (!e.axis.empty()) s.axis = vector(e.axis, allow_parameters, "a shape's axis");
    if (e.rotation) {
      s.rotation = rotation(e.rotation).matrix;
      // the drawing's shapes are constants of the run (drawn_shapes takes the parameters alone)
      if (moves_with(s.rotation, m_.symbols))
        d_.error(e.rotation->where, e.rotation->key, "a shape's rotation must not depend on the motion",
                 "turn the frame the shape is in; a shape's rotation takes constants and parameters");
    }
    out.push_back(s);
  }
  return out;
}

// The box of uniform density with the body's mass and principal moments of inertia: its sides
// are a_i = √(6 (I_j + I_k − I_i) / m), from I_i = m (a_j² + a_k²) / 12 (the diagonal of the
// tensor in the body's axes: for a tensor with products of inertia, the box of its diagonal).
Shape ModelBuilder::inertia_box(const RigidBody& body) {
  Shape s;
  s.type = Shape::Type::box;
  const GiNaC::matrix& I = body.inertia;
  for (unsigned i = 0; i < 3; ++i) {
    unsigned j = (i + 1) % 3, k = (i + 2) % 3;
    ex second_moment = (I(j, j) + I(k, k) - I(i, i)).expand();
    s.size[i] = second_moment.is_zero() || body.mass.is_zero() ? ex(0) : GiNaC::sqrt(6 * second_moment / body.mass);
  }
  return s;
}

void ModelBuilder::read_drawing() {
  std::map<std::string, int> drawn_frame;
  auto parent_of = [&](const std::string& frame) {
    auto found = drawn_frame.find(frame);
    return found == drawn_frame.end() ? -1 : found->second;
  };
  for (const FrameEntry& f : f_.frames) {
    auto placed = frames_.find(f.name);
    if (placed == frames_.end() || drawn_frame.count(f.name)) continue;
    drawn_frame[f.name] = int(m_.drawing.size());
    m_.drawing.push_back({f.name, DrawnBody::Kind::frame, placed->second.origin, placed->second.rotation.matrix,
                          parent_of(f.parent), shapes(f.shapes)});
  }
  auto rotation_in = [&](const std::string& frame) {
    auto placed = frames_.find(frame);
    return placed == frames_.end() ? identity() : placed->second.rotation.matrix;
  };
  for (std::size_t i = 0; i < f_.particles.size() && i < m_.particles.size(); ++i) {
    const ParticleEntry& p = f_.particles[i];
    std::vector<Shape> drawn = shapes(p.shapes);
    if (drawn.empty()) drawn.push_back(Shape{});  // a sphere the viewer sizes
    m_.drawing.push_back({p.name, DrawnBody::Kind::particle, m_.particles[i].position, rotation_in(p.frame),
                          parent_of(p.frame), drawn});
  }
  for (std::size_t i = 0; i < f_.rigid_bodies.size() && i < m_.rigid_bodies.size(); ++i) {
    const RigidBody& b = m_.rigid_bodies[i];
    std::vector<Shape> drawn = shapes(f_.rigid_bodies[i].shapes);
    if (drawn.empty()) drawn.push_back(inertia_box(b));
    m_.drawing.push_back({b.name, DrawnBody::Kind::rigid_body, b.center, b.rotation.matrix,
                          parent_of(f_.rigid_bodies[i].frame), drawn});
  }
  for (const PlacedPoint& p : placed_points_)
    m_.drawing.push_back({p.name, DrawnBody::Kind::point, p.position, p.rotation, parent_of(p.frame), {}});
}

}  // namespace eomgen
