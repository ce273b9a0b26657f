#include "studies/split_output.hpp"

#include <filesystem>
#include <fstream>
#include <set>

#include "common/output_file.hpp"

namespace eomgen::studies {

namespace {

namespace fs = std::filesystem;

// a file of an earlier `--split` of this model: its name, eomgen's line and the model's header in its
// first lines (a model robot_arm's units start with robot_ too, but include robot_arm.hpp)
bool earlier_split_file(const fs::path& file, const std::string& model_name, const std::string& header_name) {
  std::string name = file.filename().string(), prefix = model_name + "_";
  bool named = name == model_name + "_split.hpp" ||
               (name.rfind(prefix, 0) == 0 && name.size() > prefix.size() + 4 && name.compare(name.size() - 4, 4, ".cpp") == 0);
  if (!named) return false;
  std::ifstream in(file);
  std::string head(600, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find("(eomgen generate --split)") != std::string::npos &&
         head.find("#include \"" + header_name + "\"") != std::string::npos;
}

}  // namespace

std::string write_split_files(const std::string& folder, const std::string& model_name, const std::string& header_name,
                              const std::vector<GeneratedFile>& files) {
  std::vector<fs::path> written;
  std::set<std::string> names;
  for (const GeneratedFile& f : files) {
    fs::path at = fs::path(folder) / f.name;
    if (std::string failure = write_file_atomically(at.string(), f.text); !failure.empty()) {
      std::error_code ignored;
      for (const fs::path& w : written) fs::remove(w, ignored);
      return failure;
    }
    written.push_back(at);
    names.insert(f.name);
  }
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder.empty() ? "." : folder, ec))
    if (entry.is_regular_file(ec) && !names.count(entry.path().filename().string()) && earlier_split_file(entry.path(), model_name, header_name))
      fs::remove(entry.path(), ec);
  return "";
}

}  // namespace eomgen::studies
