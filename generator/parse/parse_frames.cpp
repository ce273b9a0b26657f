#include "parse/parse_frames.hpp"

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

// [[frames]]: name, parent, rotation, origin
void read_frames(Reader& r, const toml::node& node, ModelFile& m) {
  const toml::array* a = r.array(node, "frames", "[[frames]] tables");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    std::string key = fmt::format("frames[{}]", i);
    const toml::table* t = r.table((*a)[i], key, "name, parent, rotation, origin");
    if (!t) continue;
    r.check_keys(*t, key, {"name", "parent", "rotation", "origin"});
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
