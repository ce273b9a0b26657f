#include "parse/parse_shapes.hpp"

#include <fmt/format.h>

#include "parse/parse_frames.hpp"

namespace eomgen {

using toml_reader::Reader;

namespace {

const char* const size_hint =
    "sphere: size = [radius]; box: size = [x, y, z] (side lengths); ellipsoid: size = [a, b, c] (radii); capsule, cylinder: "
    "size = [radius, length]";

void read_shape(Reader& r, const toml::node& node, const std::string& key, std::vector<ShapeEntry>& out) {
  const toml::table* t = r.table(node, key, "type, size, offset, axis, rotation");
  if (!t) return;
  r.check_keys(*t, key, {"type", "size", "offset", "axis", "rotation"});
  ShapeEntry s;
  s.key = key;
  s.where = r.at(node);
  if (const toml::node* n = t->get("type")) {
    if (r.string(*n, key + ".type", s.type) && shape_size_count(s.type) == 0) {
      r.error(r.at(*n), key + ".type", fmt::format("'{}' is not a shape", s.type), "use sphere, box, ellipsoid, capsule or cylinder");
      return;
    }
  } else {
    r.error(s.where, key, "missing key 'type'", "add type = \"sphere\", \"box\", \"ellipsoid\", \"capsule\" or \"cylinder\"");
    return;
  }
  if (const toml::node* n = t->get("size")) {
    std::size_t count = shape_size_count(s.type);
    if (const toml::array* a = n->as_array(); a && a->size() != count) {
      r.error(r.at(*n), key + ".size", fmt::format("a {} takes {} size{}, got {}", s.type, count, count == 1 ? "" : "s", a->size()),
              size_hint);
      return;
    }
    if (!r.vector(*n, key + ".size", count, s.size)) return;
  } else {
    r.error(s.where, key, fmt::format("missing key 'size' of the {}", s.type), size_hint);
    return;
  }
  if (const toml::node* n = t->get("offset")) r.vector(*n, key + ".offset", 3, s.offset);
  if (const toml::node* n = t->get("axis")) {
    if (s.type == "sphere" || s.type == "box" || s.type == "ellipsoid")
      r.error(r.at(*n), key + ".axis", fmt::format("a {} has no axis", s.type),
              "only capsules and cylinders take axis = [x, y, z]; turn the others by rotation = \"...\"");
    else
      r.vector(*n, key + ".axis", 3, s.axis);
  }
  if (const toml::node* n = t->get("rotation")) s.rotation = read_rotation(r, *n, key + ".rotation");
  out.push_back(s);
}

}  // namespace

std::size_t shape_size_count(const std::string& type) {
  if (type == "sphere") return 1;
  if (type == "box" || type == "ellipsoid") return 3;
  if (type == "capsule" || type == "cylinder") return 2;
  return 0;
}

void read_shapes(Reader& r, const toml::table& entry, const std::string& key, std::vector<ShapeEntry>& out) {
  const toml::node* n = entry.get("shape");
  if (!n) return;
  if (const toml::array* a = n->as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) read_shape(r, (*a)[i], fmt::format("{}.shape[{}]", key, i), out);
    return;
  }
  read_shape(r, *n, key + ".shape", out);
}

}  // namespace eomgen
