#include "compile/compile_cache.hpp"

#include <dlfcn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include <fmt/format.h>

namespace eomgen::runtime {

extern const char* const model_abi_text;
extern const char* const reference_solution_text;

namespace fs = std::filesystem;

LoadedModel::~LoadedModel() {
  if (library_) dlclose(library_);
}

std::string cache_directory() {
  if (const char* dir = std::getenv("EOMGEN_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/eomgen";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/eomgen";
  return fmt::format("/tmp/eomgen-cache-{}", ::getuid());
}

std::string cxx_compiler() {
  if (const char* cxx = std::getenv("EOMGEN_CXX"); cxx && *cxx) return cxx;
  return EOMGEN_CXX_COMPILER;
}

namespace {

// GCC's time grows faster than linearly in the size of one straight-line function, most of it in
// register allocation: the nonlinear bicycle's header (1.1 MB, most of it its Lagrange I Jacobian)
// took minutes at -O2, 88 s at -O1 and 9 s at -O0 (2026-11-28), and a 10 s simulation of it took at
// most a second or two longer at -O0; so near a megabyte the first answer comes a minute sooner at
// -O0, while a long run that pays for -O1 can build the header with its own flags
constexpr std::size_t large_header_bytes = 400'000;
constexpr std::size_t huge_header_bytes = 800'000;

std::string compile_flags(const std::string& header_text) {
  std::size_t size = header_text.size();
  const char* level = size > huge_header_bytes ? "-O0" : size > large_header_bytes ? "-O1" : "-O2";
  return fmt::format("-std=c++17 {} -fPIC -shared {}", level, EOMGEN_DRIVER_REFERENCE_FLAGS);
}

std::string content_key(const std::string& header_text) {
  std::uint64_t h = 1469598103934665603ull;
  for (const std::string& part : {std::string(EOMGEN_VERSION), cxx_compiler(),
                                  compile_flags(header_text), std::string(model_abi_text),
                                  std::string(reference_solution_text), header_text})
    for (unsigned char c : part + '\x1f') {
      h ^= c;
      h *= 1099511628211ull;
    }
  return fmt::format("{:016x}", h);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string first_lines(const std::string& text, int count) {
  std::size_t at = 0;
  for (int k = 0; k < count; ++k) {
    at = text.find('\n', at);
    if (at == std::string::npos) return text;
    ++at;
  }
  return at < text.size() ? text.substr(0, at) + "[...]\n" : text;
}

// loads and checks an entry; null when it is missing or not what the key promises
std::unique_ptr<LoadedModel> open_entry(const fs::path& library, const std::string& key, bool compiled_now) {
  if (!fs::exists(library)) return nullptr;
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) return nullptr;
  auto entry = reinterpret_cast<const eomgen_model_abi* (*)()>(dlsym(handle, "eomgen_model"));
  const eomgen_model_abi* abi = entry ? entry() : nullptr;
  if (!abi || abi->abi_version != EOMGEN_MODEL_ABI_VERSION || key != abi->build_key) {
    dlclose(handle);
    return nullptr;
  }
  auto loaded = std::make_unique<LoadedModel>(handle, abi, library.string(), compiled_now);
  loaded->reference = reinterpret_cast<ReferenceFunction>(dlsym(handle, "eomgen_reference"));
  auto scalar = reinterpret_cast<const char* (*)()>(dlsym(handle, "eomgen_reference_scalar"));
  loaded->reference_scalar = scalar ? scalar() : "";
  return loaded;
}

// builds in a private folder, then renames it into place: all or nothing
bool build_entry(const fs::path& entry, const std::string& header_text, const std::string& name,
                 const std::string& key, std::string& error, bool& compiler_missing) {
  std::mt19937_64 random(std::random_device{}());
  fs::path work = entry.parent_path() / fmt::format(".build-{}-{}-{:x}", key, ::getpid(), random());
  fs::create_directories(work);
  std::ofstream(work / "model_abi.h") << model_abi_text;
  std::ofstream(work / "reference_solution.hpp") << reference_solution_text;
  std::ofstream(work / (name + ".hpp")) << header_text;
  std::ofstream(work / "driver.cpp") << fmt::format(
      "// built by eomgen {} around {}.hpp\n#include \"model_abi.h\"\n#include \"reference_solution.hpp\"\n"
      "#include \"{}.hpp\"\nEOMGEN_MODEL_ENTRY({}, \"{}\")\nEOMGEN_REFERENCE_ENTRY({})\n",
      EOMGEN_VERSION, name, name, name, key, name);
  std::string compiler = cxx_compiler();
  std::string command = fmt::format("cd '{}' && '{}' {} -o model.so driver.cpp {} > compile.log 2>&1", work.string(),
                                    compiler, compile_flags(header_text), EOMGEN_DRIVER_REFERENCE_LIBRARIES);
  int status = std::system(command.c_str());
  if (status != 0) {
    // kept for inspection beside the cache's entries, under a name no lookup uses
    fs::path kept = entry.parent_path() / fmt::format("failed-{}-{}", name, key);
    std::error_code ec;
    fs::remove_all(kept, ec);
    fs::rename(work, kept, ec);
    if (ec) kept = work;
    compiler_missing = WIFEXITED(status) && WEXITSTATUS(status) == 127;
    error = compiler_missing ? fmt::format("the C++ compiler '{}' was not found: install one (apt-get install g++) or name it in "
                                  "EOMGEN_CXX; the generated header is kept in {}",
                                  compiler, kept.string())
                    : fmt::format("compiling the generated code with '{}' failed; the header and the full log are kept in "
                                  "{} (a compiler that works on other models means a bug in eomgen: please report it). "
                                  "The compiler said:\n{}",
                                  compiler, kept.string(), first_lines(read_text(kept / "compile.log"), 20));
    return false;
  }
  std::error_code ec;
  fs::rename(work, entry, ec);
  if (ec) fs::remove_all(work);  // another process finished first; its entry is used
  return true;
}

}  // namespace

std::unique_ptr<LoadedModel> load_compiled_model(const std::string& header_text, const std::string& name,
                                                 std::string& error, bool* compiler_missing) {
  std::string key = content_key(header_text);
  fs::path root = cache_directory();
  std::error_code ec;
  fs::create_directories(root, ec);
  if (ec) {
    error = fmt::format("cannot create the cache folder {}: {} (set EOMGEN_CACHE_DIR to another folder)", root.string(),
                        ec.message());
    return nullptr;
  }
  fs::path entry = root / fmt::format("{}-{}", name, key);
  if (auto loaded = open_entry(entry / "model.so", key, false)) return loaded;
  if (fs::exists(entry)) {
    // corrupt or foreign: move it aside (atomic), then remove it
    fs::path trash = root / fmt::format(".stale-{}-{}", key, ::getpid());
    fs::rename(entry, trash, ec);
    fs::remove_all(trash, ec);
  }
  std::cerr << fmt::format("eomgen: compiling {} with {} (cached in {})\n", name, cxx_compiler(), root.string());
  bool missing = false;
  if (!build_entry(entry, header_text, name, key, error, missing)) {
    if (compiler_missing) *compiler_missing = missing;
    return nullptr;
  }
  if (auto loaded = open_entry(entry / "model.so", key, true)) return loaded;
  error = fmt::format("the compiled model in {} cannot be loaded: {}", entry.string(), dlerror() ? dlerror() : "unknown");
  return nullptr;
}

}  // namespace eomgen::runtime
