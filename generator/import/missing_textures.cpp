#include "import/missing_textures.hpp"

#include <algorithm>
#include <regex>

#include "import/xml_text.hpp"

namespace eomgen {

std::optional<UnreadableDrawing> unreadable_drawing(const std::string& message) {
  // MuJoCo 2.2.2's words (src/user/user_texture.cc, user_mesh.cc): "could not open texture file 'a.jpg'",
  // "PNG file load error '…' in texture id = 2", "could not open SKN file 'x.skn'"; then "Object name = …"
  static const std::regex texture_file("could not open texture file '([^']+)'"), png("PNG file load error '[^']*' in texture"),
      skin("could not open SKN file '([^']+)'"), object("Object name = ([^,\\n]*),");
  std::smatch m, named;
  std::string name = std::regex_search(message, named, object) ? named[1].str() : "";
  if (std::regex_search(message, m, texture_file)) return UnreadableDrawing{"texture", name, m[1].str()};
  if (std::regex_search(message, m, png)) return UnreadableDrawing{"texture", name, ""};
  if (std::regex_search(message, m, skin)) return UnreadableDrawing{"skin", name, m[1].str()};
  return std::nullopt;
}

namespace {

const char* const texture_files[] = {"file", "fileright", "fileleft", "fileup", "filedown", "filefront", "fileback"};

// a texture without a name takes its file's, without folder and extension (MuJoCo 2.2.2's mjCModel::CheckEmptyNames)
std::string name_from_file(const std::string& file) {
  std::string stem = file.substr(file.find_last_of("/\\") == std::string::npos ? 0 : file.find_last_of("/\\") + 1);
  return stem.substr(0, stem.rfind('.'));
}

// whether the tag [at, end) is the texture MuJoCo named (or, when it names none, any unnamed one that reads a file)
bool is_the_named_one(const std::string& text, std::size_t at, std::size_t end, const UnreadableDrawing& drawing) {
  std::optional<std::string> name = attribute(text, at, end, "name");
  if (name && !name->empty()) return *name == drawing.name;
  if (!drawing.name.empty()) {
    std::optional<std::string> file = attribute(text, at, end, "file");
    return file && name_from_file(*file) == drawing.name;
  }
  return std::any_of(std::begin(texture_files), std::end(texture_files),
                     [&](const char* file) { return attribute(text, at, end, file).has_value(); });
}

void add_files_named(const std::string& text, std::size_t at, std::size_t end, std::vector<std::string>& files) {
  for (const char* attribute_name : texture_files)
    if (std::optional<std::string> file = attribute(text, at, end, attribute_name);
        file && std::find(files.begin(), files.end(), *file) == files.end())
      files.push_back(*file);
}

// a plain texture of 8 by 8 pixels where the tag says no size
bool drawn_plain(std::string& text, const UnreadableDrawing& drawing, std::vector<std::string>& files) {
  bool changed = false;
  for (std::size_t at = element_start(text, "texture"); at != std::string::npos; at = element_start(text, "texture", at + 1)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    if (!is_the_named_one(text, at, end, drawing) || attribute(text, at, end, "builtin")) continue;
    add_files_named(text, at, end, files);
    std::string plain = " builtin=\"flat\"";
    if (!attribute(text, at, end, "width")) plain += " width=\"8\"";
    if (!attribute(text, at, end, "height")) plain += " height=\"8\"";
    text.insert(at + 8, plain);
    changed = true;
  }
  return changed;
}

bool skin_left_out(std::string& text, const UnreadableDrawing& drawing, std::vector<std::string>& files) {
  bool changed = false;
  for (std::size_t at = element_start(text, "skin"); at != std::string::npos; at = element_start(text, "skin", at)) {
    std::size_t end = past_tag(text, at);
    if (end == std::string::npos) break;
    std::optional<std::string> file = attribute(text, at, end, "file");
    std::optional<std::string> name = attribute(text, at, end, "name");
    bool named = drawing.name.empty() ? file && *file == drawing.file : name && *name == drawing.name;
    if (!named) {
      at = end;
      continue;
    }
    if (file && std::find(files.begin(), files.end(), *file) == files.end()) files.push_back(*file);
    if (text[end - 2] != '/') end = text.find("</skin>", end) == std::string::npos ? end : text.find("</skin>", end) + 7;
    text.erase(at, end - at);
    changed = true;
  }
  return changed;
}

}  // namespace

bool without_unreadable_drawing(std::vector<std::pair<std::string, std::string>>& sources, const UnreadableDrawing& drawing,
                                std::vector<std::string>& files) {
  bool changed = false;
  for (auto& source : sources)
    changed = (drawing.element == "skin" ? skin_left_out(source.second, drawing, files) : drawn_plain(source.second, drawing, files)) ||
              changed;
  return changed;
}

}  // namespace eomgen
