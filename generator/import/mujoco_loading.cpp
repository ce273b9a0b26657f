// Loading a robot file with MuJoCo 2.2.2's compiler, from memory where the file needs changes
// first: MuJoCo 3's attributes and sensors left out (newer_mjcf.hpp) or written as 2.2.2 reads them
// (carried_newer_mjcf.hpp), placeholders for mesh files it cannot read (missing_meshes.hpp), plain textures
// and no skins for texture and skin files it cannot read (missing_textures.hpp), mass bounds
// for moving bodies without mass (massless_bodies.hpp), keyframes' trailing white space taken out
// (keyframe_text.hpp), a URDF's fixed links kept and its unreadable meshes left out (urdf_text.hpp).
#include "import/mujoco_loading.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "import/carried_newer_mjcf.hpp"
#include "import/keyframe_text.hpp"
#include "import/massless_bodies.hpp"
#include "import/missing_meshes.hpp"
#include "import/missing_textures.hpp"
#include "import/unbalanced_inertias.hpp"
#include "import/urdf_text.hpp"

namespace eomgen {

std::string text_of_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  if (file) text << file.rdbuf();
  return text.str();
}

std::vector<std::pair<std::string, std::string>> mjcf_sources(const std::string& path) {
  std::string folder = path.substr(0, path.find_last_of('/') + 1);
  std::vector<std::pair<std::string, std::string>> sources{{path, text_of_file(path)}};
  for (std::size_t k = 0; k < sources.size() && sources.size() < 64; ++k)
    for (const std::string& name : included_files(std::string(sources[k].second)))
      if (std::none_of(sources.begin(), sources.end(), [&](const auto& s) { return s.first == folder + name; }))
        sources.emplace_back(folder + name, text_of_file(folder + name));
  return sources;
}

namespace {

// files by name and text: a robot file and those it includes
using Sources = std::vector<std::pair<std::string, std::string>>;

// the texts read by MuJoCo from memory, the first under the file's own path: it finds the files it
// names beside it on disk, and those it includes among the texts (by their names without a path)
// (texts end in a 0 for the XML parser; `files`, such as meshes, are their bytes alone)
mjModel* loaded_texts(const std::string& path, const Sources& texts, char* error, int size, const Sources& files_too = {}) {
  auto files = std::make_unique<mjVFS>();
  mj_defaultVFS(files.get());
  for (const auto& [name, text] : texts) {
    if (mj_makeEmptyFileVFS(files.get(), name.c_str(), int(text.size()) + 1) != 0) {
      mj_deleteVFS(files.get());
      return mj_loadXML(path.c_str(), nullptr, error, size);
    }
    std::memcpy(files->filedata[files->nfile - 1], text.c_str(), text.size() + 1);
  }
  for (const auto& [name, bytes] : files_too) {
    if (mj_makeEmptyFileVFS(files.get(), name.c_str(), int(bytes.size())) != 0) {
      mj_deleteVFS(files.get());
      std::snprintf(error, std::size_t(size), "MuJoCo's virtual file system has no room for '%s'", name.c_str());
      return nullptr;
    }
    std::memcpy(files->filedata[files->nfile - 1], bytes.data(), bytes.size());
  }
  mjModel* model = mj_loadXML(path.c_str(), files.get(), error, size);
  mj_deleteVFS(files.get());
  return model;
}

mjModel* loaded_text(const std::string& path, const std::string& text, char* error, int size) {
  return loaded_texts(path, {{path, text}}, error, size);
}

// where no line is known, the first line that names the object, in the file (sources[0]) or in one
// it includes: an included file's elements have no line in MuJoCo's messages
UnreadableRobot located(UnreadableRobot u, const Sources& sources) {
  if (u.line > 0 || u.object.empty()) return u;
  for (std::size_t k = 0; k < sources.size(); ++k)
    if (int line = line_naming(sources[k].second, u.object); line > 0) {
      u.line = line;
      if (k > 0) u.file = sources[k].first;
      break;
    }
  return u;
}

// whether MuJoCo's message is about a mesh file it could not find or read
bool about_a_mesh(const std::string& message) {
  for (const char* mark : {"mesh", "Mesh", "STL file", "OBJ file", "MSH file"})
    if (message.find(mark) != std::string::npos) return true;
  return false;
}


// the model read with the mass bounds, or why not when a joint moves no mass (its M would be singular)
std::variant<mjModel*, UnreadableRobot> without_massless_joints(mjModel* model, const LeftOut& left_out, const Sources& sources) {
  if (!left_out.mass_bounds) return model;
  std::string joint = joint_moving_no_mass(model);
  if (joint.empty()) return model;
  mj_deleteModel(model);
  UnreadableRobot u(0, fmt::format("joint '{}' moves no body with mass or inertia, so that the robot's mass matrix is singular "
                                   "(MuJoCo refuses such moving bodies)", joint),
                    "give the bodies it moves an <inertial> with a mass and inertia");
  u.object = joint;
  u.moves_no_mass = true;
  return located(u, sources);
}

// an MJCF file, read again from memory without each attribute or sensor of a later MuJoCo that 2.2.2 refuses
// (or with it written as 2.2.2 reads it: carried_newer_mjcf.hpp), in the file and in those it includes,
// and with a placeholder for each mesh file it cannot read, kept only when no body takes its
// inertia from a mesh (missing_meshes.hpp)
std::variant<mjModel*, UnreadableRobot> loaded_mjcf(const std::string& path, char* error, int size, LeftOut& left_out) {
  mjModel* model = mj_loadXML(path.c_str(), nullptr, error, size);
  Sources sources;
  std::vector<UnreadableMesh> meshes;
  // the placeholders' edge, and twice it for the second reading: a metre, so that a mesh scaled from
  // millimetres (scale="0.001 0.001 0.001", Robotiq's) still has a volume MuJoCo accepts (above 1e-15 m³)
  const double edge = 1.0;
  auto load = [&](double mesh_size) {
    if (sources.empty()) sources = mjcf_sources(path);
    std::vector<std::pair<std::string, std::string>> placeholders;
    for (const UnreadableMesh& mesh : meshes) placeholders.push_back(*placeholder_mesh(mesh, mesh_size));
    return loaded_texts(path, sources, error, size, placeholders);
  };
  // the file's text and those it includes: a negative mass in any of them, which the bounds would hide
  auto source_texts = [&] {
    if (sources.empty()) sources = mjcf_sources(path);
    std::vector<std::string> texts;
    for (const auto& source : sources) texts.push_back(source.second);
    return texts;
  };
  for (int round = 0; !model && round < 400; ++round) {
    if (!left_out.mass_bounds && refuses_massless_bodies(error, source_texts())) {
      std::string bounded = with_mass_bounds(sources[0].second);
      if (bounded == sources[0].second) break;
      sources[0].second = bounded;
      left_out.mass_bounds = true;
      model = load(edge);
      continue;
    }
    if (std::optional<UnreadableMesh> mesh = unreadable_mesh(error); mesh && placeholder_mesh(*mesh, 1)) {
      auto same = [&](const UnreadableMesh& m) { return m.file == mesh->file; };
      if (std::any_of(meshes.begin(), meshes.end(), same)) break;  // its placeholder did not help
      meshes.push_back(*mesh);
      model = load(edge);
      continue;
    }
    if (std::optional<UnreadableDrawing> drawing = unreadable_drawing(error)) {
      if (sources.empty()) sources = mjcf_sources(path);
      if (!without_unreadable_drawing(sources, *drawing, left_out.unread_drawing_files)) break;
      model = load(edge);
      continue;
    }
    if (refuses_keyframe_length(error)) {
      if (sources.empty()) sources = mjcf_sources(path);
      bool edited = false;
      for (auto& source : sources) {
        std::string trimmed = with_keyframe_values_trimmed(source.second);
        edited = edited || trimmed != source.second;
        source.second = trimmed;
      }
      if (!edited) break;
      model = load(edge);
      continue;
    }
    if (refuses_carried_attribute(error)) {
      if (sources.empty()) sources = mjcf_sources(path);
      if (translate_carried_attribute(error, sources, left_out)) {
        model = load(edge);
        continue;
      }
    }
    std::optional<NewerMjcf> newer = newer_mjcf_refused(error);
    if (!newer) break;
    if (sources.empty()) sources = mjcf_sources(path);
    bool edited = false;
    for (auto& [name, text] : sources) {
      std::string without = without_newer_mjcf(text, *newer);
      edited = edited || without != text;
      text = without;
    }
    if (!edited) break;
    left_out.newer.push_back(*newer);
    model = load(edge);
  }
  if (!model) return model;
  if (meshes.empty()) return without_massless_joints(model, left_out, sources);
  std::unique_ptr<mjModel, void (*)(mjModel*)> larger(load(2 * edge), mj_deleteModel);
  if (!larger) {
    mj_deleteModel(model);
    return nullptr;
  }
  MeshDependence dependence = mesh_dependence(model, larger.get());
  // named as the file names them, relative to its folder (MuJoCo's message has the folder in front)
  std::string folder = path.substr(0, path.find_last_of('/') + 1), files;
  for (std::size_t k = 0; k < meshes.size() && k < 3; ++k) {
    const std::string& file = meshes[k].file;
    files += (k ? ", '" : "'") + (file.rfind(folder, 0) == 0 ? file.substr(folder.size()) : file) + "'";
  }
  if (meshes.size() > 3) files += fmt::format(" and {} more", meshes.size() - 3);
  if (!dependence.body.empty()) {
    mj_deleteModel(model);
    UnreadableRobot u(0, fmt::format("body '{}' takes its mass and inertia from its geoms, a mesh among them, and MuJoCo "
                                     "cannot read the mesh file(s) {}", dependence.body, files),
                      "put the mesh files where the file names them, or give the body an <inertial>");
    u.object = dependence.body;
    return located(u, sources);
  }
  left_out.unread_mesh_files = int(meshes.size());
  left_out.unread_mesh_names = files;
  left_out.mesh_sized_geoms = dependence.geoms;
  return without_massless_joints(model, left_out, sources);
}

}  // namespace

// a URDF is read with its fixed links kept (urdf_text.hpp); what its reader would crash on is
// reported first, and when MuJoCo cannot read its meshes (ROS packages' COLLADA files and
// package:// paths) it is read again without them
std::variant<mjModel*, UnreadableRobot> loaded_model(const std::string& path, const std::string& urdf, char* error, int size,
                                                     LeftOut& left_out) {
  if (urdf.empty()) return loaded_mjcf(path, error, size, left_out);
  if (UrdfTextMistake mistake = urdf_text_mistake(urdf, path); mistake.line > 0)
    return UnreadableRobot{mistake.line, mistake.message, mistake.hint};
  std::string kept = with_static_links_kept(urdf);
  // the text, or when MuJoCo refuses its massless moving bodies, an inertia with A + B < C or, fusing
  // fixed links, a moment below zero, the text with the mass bounds, balanceinertia or positive
  // moments (each kept for a second reading without meshes; the stated inertias are given back later)
  auto load = [&](std::string text) {
    if (left_out.mass_bounds) text = with_mass_bounds(text);
    if (left_out.balanced_inertias) text = with_balanced_inertias(text);
    if (left_out.positive_moments) text = with_positive_moments(text);
    for (;;) {
      mjModel* loaded = loaded_text(path, text, error, size);
      if (loaded) return loaded;
      std::string next = text;
      if (!left_out.mass_bounds && refuses_massless_bodies(error, {text})) {
        next = with_mass_bounds(text);
        left_out.mass_bounds = next != text;
      } else if (!left_out.balanced_inertias && refuses_unbalanced_inertia(error)) {
        next = with_balanced_inertias(text);
        left_out.balanced_inertias = next != text;
      } else if (!left_out.positive_moments && refuses_to_fuse_singular_inertias(error)) {
        next = with_positive_moments(text);
        left_out.positive_moments = next != text;
      }
      if (next == text) return loaded;
      text = next;
    }
  };
  mjModel* model = load(kept);
  if (model) return without_massless_joints(model, left_out, {{path, urdf}});
  if (!about_a_mesh(error)) return model;
  int left_out_meshes = 0;
  std::string first_error = error;
  std::string without = without_mesh_geometry(kept, left_out_meshes);
  if (left_out_meshes == 0) return nullptr;
  model = load(without);
  if (!model) {
    // what stops it now, said to be of the file without its meshes
    std::string second = error;
    std::size_t end = second.find('\n');
    second.insert(end == std::string::npos ? second.size() : end,
                  fmt::format(" (read without its {} mesh(es), which MuJoCo could not read)", left_out_meshes));
    std::snprintf(error, std::size_t(size), "%s", second.c_str());
    return nullptr;
  }
  left_out.meshes = left_out_meshes;
  left_out.mesh_error = first_error;
  return without_massless_joints(model, left_out, {{path, urdf}});
}

UnreadableRobot unreadable_robot(const std::string& text) {
  UnreadableRobot u;
  // the last of these that the text has names the line: "Element 'body', line 5" beats a nested parse error's
  for (const char* marker : {"Line number=", "line = ", "', line "})
    if (std::size_t at = text.find(marker); at != std::string::npos) u.line = std::atoi(text.c_str() + at + std::strlen(marker));
  std::string first = text.substr(0, text.find('\n'));
  for (const char* prefix : {"Error: ", "XML Error: "})
    if (first.rfind(prefix, 0) == 0) first = first.substr(std::strlen(prefix));
  if (first.rfind("XML parse error", 0) == 0) first = "the XML is malformed";
  if (std::size_t at = text.find("XML_ERROR_FILE_NOT_FOUND"); at != std::string::npos) {
    std::size_t name = text.find("filename=", at);
    first = "an included file does not exist" +
            (name == std::string::npos ? "" : ": " + text.substr(name + 9, text.find_first_of("'\n", name) - name - 9));
  }
  if (std::size_t at = text.find("Element '"); at != std::string::npos)
    first += " (element <" + text.substr(at + 9, text.find('\'', at + 9) - at - 9) + ">)";
  while (!first.empty() && std::isspace(static_cast<unsigned char>(first.back()))) first.pop_back();
  if (std::size_t at = text.find("Object name = "); at != std::string::npos)
    u.object = text.substr(at + 14, text.find_first_of(",\n", at + 14) - at - 14);
  // no line (as for an element of an included file): the object's name is what finds it
  if (u.line <= 0 && !u.object.empty()) first += " ('" + u.object + "')";
  u.message = first;
  return u;
}

UnreadableRobot unreadable_mjcf(const std::string& mujoco_error, const std::string& path) {
  UnreadableRobot u = unreadable_robot(mujoco_error);
  if (std::optional<std::string> hint = newer_element_hint(mujoco_error)) u.hint = *hint;
  return u.line > 0 || u.object.empty() ? u : located(u, mjcf_sources(path));
}

}  // namespace eomgen
