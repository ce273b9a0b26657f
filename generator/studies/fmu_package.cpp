#include "studies/fmu_package.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <unistd.h>

#include "common/output_file.hpp"
#include "common/version.hpp"
#include "common/zip_archive.hpp"
#include "emit/cpp_header.hpp"
#include "fmu/fmu_binary.hpp"
#include "fmu/fmu_nominals.hpp"

namespace eomgen::studies {

std::string write_fmu(const Equations& e, const std::string& directory, FmuKinds kinds, std::string& path) {
  if (e.has_multipliers)
    return fmt::format("{} is a Lagrange I model: an FMU of it would need the multipliers' solver; derive it with "
                       "method = \"appell\" or \"lagrange2\" in minimal coordinates instead",
                       e.model_name);
  std::string header = emit_cpp_header(e), guid = fmu_guid(header);
  std::string library = (std::filesystem::temp_directory_path() / fmt::format("eomgen-{}-{}.so", e.model_name, ::getpid())).string();
  if (std::string failure = runtime::build_fmu_binary(header, e.model_name, guid, library, kinds.co_simulation);
      !failure.empty())
    return failure;
  std::string no_nominals;
  std::vector<double> nominals = runtime::fmu_state_nominals(library, guid, e.symbols.num_coordinates() + e.num_velocities(), no_nominals);
  if (!no_nominals.empty()) {
    std::filesystem::remove(library);
    return "the FMU's states' nominal values: " + no_nominals;
  }
  std::string description = fmi2_model_description(e, guid, kinds, version_string, nominals);
  std::ifstream in(library, std::ios::binary);
  std::ostringstream binary;
  binary << in.rdbuf();
  std::filesystem::remove(library);
  path = (std::filesystem::path(directory) / (e.model_name + ".fmu")).string();
  return write_file_atomically(path, zip_archive({{"modelDescription.xml", description},
                                                  {"binaries/linux64/" + e.model_name + ".so", binary.str()}}));
}

}  // namespace eomgen::studies
