#include "fmu/fmu_binary.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <unistd.h>

#include "compile/compile_cache.hpp"

namespace eomgen::runtime {

extern const char* const fmi2_header_text;
extern const char* const fmi2_model_text;

namespace fs = std::filesystem;

std::string build_fmu_binary(const std::string& header_text, const std::string& name, const std::string& guid,
                             const std::string& library_path, bool co_simulation) {
  fs::path work = fs::temp_directory_path() / fmt::format("eomgen-fmu-{}-{}", name, ::getpid());
  std::error_code ec;
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec) return fmt::format("cannot create {}: {}", work.string(), ec.message());
  std::ofstream(work / (name + ".hpp")) << header_text;
  std::ofstream(work / "fmi2.h") << fmi2_header_text;
  std::ofstream(work / "fmi2_model.hpp") << fmi2_model_text;
  std::ofstream(work / "fmu.cpp") << fmt::format(
      "// the FMU binary of {0}, built by eomgen\n#include \"{0}.hpp\"\n#define EOMGEN_FMU_MODEL {0}\n"
      "#define EOMGEN_FMU_GUID \"{1}\"\n{2}#include \"fmi2_model.hpp\"\n",
      name, guid, co_simulation ? "#define EOMGEN_FMU_CO_SIMULATION\n" : "");
  std::string command = fmt::format(
      "cd '{}' && '{}' -std=c++17 -O2 -fPIC -shared -o model.so fmu.cpp {} > compile.log 2>&1", work.string(), cxx_compiler(),
      co_simulation ? "-lsundials_cvode -lsundials_nvecserial -lsundials_sunlinsoldense -lsundials_sunmatrixdense" : "");
  if (std::system(command.c_str()) != 0) {
    std::ifstream log(work / "compile.log");
    std::ostringstream first;
    std::string line;
    for (int k = 0; k < 20 && std::getline(log, line); ++k) first << line << "\n";
    return fmt::format("compiling the FMU binary with '{}' failed; kept in {}. The compiler said:\n{}", cxx_compiler(),
                       work.string(), first.str());
  }
  fs::copy_file(work / "model.so", library_path, fs::copy_options::overwrite_existing, ec);
  if (ec) return fmt::format("cannot write {}: {}", library_path, ec.message());
  fs::remove_all(work, ec);
  return {};
}

}  // namespace eomgen::runtime
