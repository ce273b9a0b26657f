#include "parse/parse_frames.hpp"

#include "parse/parse_shapes.hpp"

#include <fmt/format.h>

namespace eomgen {

using toml_reader::Reader;

std::optional<RotationEntry> read_rotation(Reader& r, const toml::node& node, const std::string& key) {
  RotationEntry rot{std::nullopt, {}, r.at(node), key};
  if (node.is_string()) {
    ExpressionText text;
    r.expression(node, key, text);
    rot.product = text;
  } else if (node.is_array()) {
    r.matrix3(node, key, rot.matrix);
  } else {
    r.error(r.at(node), key, fmt::format("expected a rotation, got {}", toml_reader::type_name(node)),
            "write e.g. \"euler313(psi, theta, phi)\", \"rot_z(a)*rot_x(b)\" or a 3x3 array");
    return std::nullopt;
  }
  return rot;
}

void read_frame_name(Reader& r, const toml::table& t, const std::string& key, std::string& name,
                     SourceLocation& where) {
  const toml::node* n = t.get("frame");
  if (!n) return;
  where = r.at(*n);
  where.column += 1;  // the opening quote
  if (r.string(*n, key + ".frame", name) && name == "inertial") name.clear();
}

namespace {

// a list of `count` names, e.g. quaternion = ["qw", "qx", "qy", "qz"]
void read_names(Reader& r, const toml::node& node, const std::string& key, std::size_t count,
                std::vector<std::string>& out, SourceLocation& where) {
  where = r.at(node);
  const toml::array* a = node.as_array();
  if (!a || a->size() != count) {
    r.error(where, key, fmt::format("expected {} names", count), fmt::format("write {} names from the model, e.g. {}", count,
            count == 4 ? "[\"qw\", \"qx\", \"qy\", \"qz\"]" : "[\"wx\", \"wy\", \"wz\"]"));
    return;
  }
  out.assign(count, "");
  for (std::size_t i = 0; i < count; ++i) r.string(*a->get(i), fmt::format("{}[{}]", key, i), out[i]);
}

const char* const joint_types = "write type = \"revolute\", \"prismatic\", \"ball\", \"free\" or \"fixed\"";

// the keys of a ball or free joint: quaternion, angular_velocity, initial_angular_velocity, position
void read_spherical_joint(Reader& r, const toml::table& t, const std::string& key, JointEntry& j) {
  bool free = j.type == "free";
  if (const toml::node* n = t.get("quaternion")) read_names(r, *n, key + ".quaternion", 4, j.quaternion, j.quaternion_where);
  else
    r.error(j.where, key, fmt::format("a {} joint needs the coordinates of its quaternion", j.type),
            "add quaternion = [\"qw\", \"qx\", \"qy\", \"qz\"], four names from [coordinates] (w first)");
  if (const toml::node* n = t.get("angular_velocity"))
    read_names(r, *n, key + ".angular_velocity", 3, j.angular_velocity, j.angular_velocity_where);
  else
    r.error(j.where, key, fmt::format("a {} joint needs names for its angular velocity", j.type),
            "add angular_velocity = [\"wx\", \"wy\", \"wz\"]: the components in the frame, the joint's velocities");
  if (const toml::node* n = t.get("initial_angular_velocity")) r.vector(*n, key + ".initial_angular_velocity", 3, j.initial_angular_velocity);
  if (const toml::node* n = t.get("position")) {
    if (free) read_names(r, *n, key + ".position", 3, j.position, j.position_where);
    else r.error(r.at(*n), key + ".position", "a ball joint has no position", "use type = \"free\" for a body that also translates");
  } else if (free) {
    r.error(j.where, key, "a free joint needs the coordinates of its position",
            "add position = [\"x\", \"y\", \"z\"], three names from [coordinates] (in the parent's axes)");
  }
  if (const toml::node* n = t.get("axis"))
    r.error(r.at(*n), key + ".axis", fmt::format("a {} joint has no axis", j.type), "it turns about every axis; leave it out");
  if (const toml::node* n = t.get("coordinate"))
    r.error(r.at(*n), key + ".coordinate", fmt::format("a {} joint is moved by its quaternion, not one coordinate", j.type),
            "name its coordinates with quaternion = [...]");
  if (const toml::node* n = t.get("anchor"); n && free)
    r.error(r.at(*n), key + ".anchor", "a free joint has no anchor", "it turns about the frame's origin; leave it out");
}

// joint = { type = "revolute", axis = [...], anchor = [...], coordinate = "q" }
std::optional<JointEntry> read_joint(Reader& r, const toml::node& node, const std::string& key) {
  const toml::table* t = r.table(node, key, "type, axis, anchor, coordinate");
  if (!t) return std::nullopt;
  r.check_keys(*t, key, {"type", "axis", "anchor", "coordinate", "multiplier", "offset", "quaternion", "angular_velocity",
                         "initial_angular_velocity", "position"});
  JointEntry j;
  j.key = key;
  j.where = r.at(node);
  if (const toml::node* n = t->get("type")) {
    j.type_where = r.at(*n);
    j.type_where.column += 1;
    if (r.string(*n, key + ".type", j.type) && j.type != "revolute" && j.type != "prismatic" && j.type != "fixed" &&
        j.type != "ball" && j.type != "free")
      r.error(j.type_where, key + ".type", fmt::format("'{}' is not a joint type", j.type), joint_types);
  } else {
    r.error(j.where, key, "the joint has no type", joint_types);
  }
  for (const char* follows : {"multiplier", "offset"})
    if (const toml::node* n = t->get(follows)) {
      if (j.type != "revolute" && j.type != "prismatic") {
        r.error(r.at(*n), key + "." + follows, fmt::format("a {} joint has no {}", j.type.empty() ? "typeless" : j.type, follows),
                "only a revolute or prismatic joint follows a coordinate by multiplier·q + offset; leave it out");
        continue;
      }
      ExpressionText e;
      if (r.expression(*n, key + "." + follows, e)) (follows[0] == 'm' ? j.multiplier : j.offset) = e;
    }
  if (j.type == "ball" || j.type == "free") {
    read_spherical_joint(r, *t, key, j);
    if (const toml::node* n = t->get("anchor"); n && j.type == "ball") r.vector(*n, key + ".anchor", 3, j.anchor);
    return j;
  }
  for (const char* spherical : {"quaternion", "angular_velocity", "initial_angular_velocity", "position"})
    if (const toml::node* n = t->get(spherical))
      r.error(r.at(*n), key + "." + spherical, fmt::format("a {} joint has no {}", j.type.empty() ? "typeless" : j.type, spherical),
              "only ball and free joints have a quaternion and an angular velocity");
  bool moves = j.type != "fixed";
  if (const toml::node* n = t->get("axis")) r.vector(*n, key + ".axis", 3, j.axis);
  else if (moves && !j.type.empty())
    r.error(j.where, key, fmt::format("a {} joint needs an axis", j.type), "add axis = [x, y, z] in the frame's coordinates");
  if (const toml::node* n = t->get("anchor")) {
    r.vector(*n, key + ".anchor", 3, j.anchor);
    if (j.type == "prismatic" || j.type == "fixed")
      r.error(r.at(*n), key + ".anchor", fmt::format("a {} joint has no anchor", j.type),
              "an anchor is the point a revolute joint turns about; leave it out");
  }
  if (const toml::node* n = t->get("coordinate")) {
    j.coordinate_where = r.at(*n);
    j.coordinate_where.column += 1;
    r.string(*n, key + ".coordinate", j.coordinate);
    if (!moves)
      r.error(j.coordinate_where, key + ".coordinate", "a fixed joint has no coordinate", "leave it out");
  } else if (moves && !j.type.empty()) {
    r.error(j.where, key, fmt::format("a {} joint needs the coordinate that moves it", j.type),
            "add coordinate = \"q\", a name from [coordinates]");
  }
  return j;
}

}  // namespace

// [[frames]]: name, parent, rotation, origin, joint
void read_frames(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "frames", "[[frames]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("frames[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "name, parent, rotation, origin, joint");
    if (!t) continue;
    r.check_keys(*t, key, {"name", "parent", "rotation", "origin", "joint", "shape"});
    FrameEntry f;
    f.key = key;
    f.where = r.at((*a)[i]);
    if (const toml::node* n = t->get("name")) r.string(*n, key + ".name", f.name);
    else r.error(f.where, key, "missing key 'name'", "give every frame a name = \"...\"");
    if (const toml::node* n = t->get("parent")) {
      f.parent_where = r.at(*n);
      f.parent_where.column += 1;
      if (r.string(*n, key + ".parent", f.parent) && f.parent == "inertial") f.parent.clear();
    }
    if (const toml::node* n = t->get("rotation")) f.rotation = read_rotation(r, *n, key + ".rotation");
    if (const toml::node* n = t->get("origin")) r.vector(*n, key + ".origin", 3, f.origin);
    if (const toml::node* n = t->get("joint")) f.joint = read_joint(r, *n, key + ".joint");
    read_shapes(r, *t, key, f.shapes);
    m.frames.push_back(f);
  }
}

// [[points]]: name, frame, position
void read_points(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "points", "[[points]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("points[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "name, frame, position");
    if (!t) continue;
    r.check_keys(*t, key, {"name", "frame", "position"});
    PointEntry p;
    p.key = key;
    p.where = r.at((*a)[i]);
    if (const toml::node* n = t->get("name")) r.string(*n, key + ".name", p.name);
    else r.error(p.where, key, "missing key 'name'", "give every point a name = \"...\"");
    read_frame_name(r, *t, key, p.frame, p.frame_where);
    if (const toml::node* n = t->get("position")) r.vector(*n, key + ".position", 3, p.position);
    else r.error(p.where, key, "missing key 'position'", "add position = [\"x\", \"y\", \"z\"] in the point's frame");
    m.points.push_back(p);
  }
}

}  // namespace eomgen
