#include "import/missing_meshes.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <regex>

#include <fmt/format.h>

namespace eomgen {

std::optional<UnreadableMesh> unreadable_mesh(const std::string& message) {
  // MuJoCo 2.2.2's words (src/user/user_mesh.cc) for a file it cannot open or whose content it rejects
  static const std::regex said(
      "(?:could not open|could not parse|invalid header in|missing header in|invalid sizes in|unexpected file size in) "
      "(STL|OBJ|MSH) file '([^']+)'");
  std::smatch m;
  if (!std::regex_search(message, m, said)) return std::nullopt;
  return UnreadableMesh{m[2].str(), m[1].str()};
}

namespace {

// the corners (0,0,0), (s,0,0), (0,s,0), (0,0,s), each face listed counter-clockwise seen from outside
const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string binary_stl(double size) {
  float corner[4][3] = {{0, 0, 0}, {float(size), 0, 0}, {0, float(size), 0}, {0, 0, float(size)}};
  std::string out(80, ' ');  // the header, which must not begin with "solid"
  auto append = [&](const void* bytes, std::size_t count) { out.append(static_cast<const char*>(bytes), count); };
  std::uint32_t count = 4;
  append(&count, 4);
  for (const auto& face : faces) {
    float normal[3] = {0, 0, 0};
    append(normal, sizeof normal);  // MuJoCo computes its own normals
    for (int v : face) append(corner[v], sizeof corner[v]);
    std::uint16_t attributes = 0;
    append(&attributes, 2);
  }
  return out;
}

std::string obj(double size) {
  std::string out = fmt::format("v 0 0 0\nv {0} 0 0\nv 0 {0} 0\nv 0 0 {0}\n", size);
  for (const auto& face : faces) out += fmt::format("f {} {} {}\n", face[0] + 1, face[1] + 1, face[2] + 1);
  return out;
}

bool differ(const mjtNum* a, const mjtNum* b, int count) {
  for (int k = 0; k < count; ++k)
    if (a[k] != b[k]) return true;
  return false;
}

}  // namespace

std::optional<std::pair<std::string, std::string>> placeholder_mesh(const UnreadableMesh& mesh, double size) {
  std::string name = mesh.file.substr(mesh.file.find_last_of("/\\") + 1);  // MuJoCo's VFS matches names without a path
  if (mesh.format == "STL") return std::make_pair(name, binary_stl(size));
  if (mesh.format == "OBJ") return std::make_pair(name, obj(size));
  return std::nullopt;
}

MeshDependence mesh_dependence(const mjModel* small, const mjModel* large) {
  MeshDependence d;
  for (int b = 1; b < small->nbody && d.body.empty(); ++b)
    if (small->body_mass[b] != large->body_mass[b] || differ(small->body_ipos + 3 * b, large->body_ipos + 3 * b, 3) ||
        differ(small->body_inertia + 3 * b, large->body_inertia + 3 * b, 3) ||
        differ(small->body_iquat + 4 * b, large->body_iquat + 4 * b, 4))
      d.body = small->names + small->name_bodyadr[b];
  for (int g = 0; g < small->ngeom; ++g)
    if (differ(small->geom_size + 3 * g, large->geom_size + 3 * g, 3) || differ(small->geom_pos + 3 * g, large->geom_pos + 3 * g, 3) ||
        differ(small->geom_quat + 4 * g, large->geom_quat + 4 * g, 4))
      d.geoms.push_back(g);
  return d;
}

}  // namespace eomgen
