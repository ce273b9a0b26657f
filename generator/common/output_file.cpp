#include "common/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace eomgen {

std::string output_file_refusal(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(path, error))
    return path + " is a folder, not a file: name a file in it";
  // a device or a pipe takes the output itself: its folder (/dev) need not be writable
  if (is_device_or_pipe(path))
    return ::access(path.c_str(), W_OK) == 0 ? std::string() : "cannot write " + path + ": " + std::strerror(errno);
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, error)) return "cannot write " + path + ": the folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0) return "cannot write " + path + ": the folder " + folder.string() + " is not writable";
  return {};
}

bool is_device_or_pipe(const std::string& path) {
  std::error_code error;
  auto existing = std::filesystem::status(path, error);
  return !error && std::filesystem::exists(existing) && !std::filesystem::is_regular_file(existing) &&
         !std::filesystem::is_directory(existing);
}

namespace {

// A device or a pipe takes the text as it comes: renaming a file over it would replace it,
// /dev/null included when run as root.
std::string write_into_special_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) return "cannot open " + path + ": " + std::strerror(errno);
  out << text;
  out.flush();
  if (!out) return "cannot write " + path + ": " + std::strerror(errno);
  return {};
}

}  // namespace

std::string write_file_atomically(const std::string& path, const std::string& text) {
  if (std::string refusal = output_file_refusal(path); !refusal.empty()) return refusal;
  if (is_device_or_pipe(path)) return write_into_special_file(path, text);
  std::string temporary = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot create " + temporary + ": " + std::strerror(errno);
    out << text;
    out.flush();
    if (!out) {
      std::string why = std::strerror(errno);
      std::remove(temporary.c_str());
      return "cannot write " + path + " (the disk is full, or a file-size limit is reached): " + why;
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::string why = std::strerror(errno);
    std::remove(temporary.c_str());
    return "cannot move the output into place at " + path + ": " + why;
  }
  return {};
}

std::string make_output_directory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) return "cannot create the output folder " + directory + ": " + error.message();
  if (!std::filesystem::is_directory(directory, error)) return directory + " is not a folder";
  return {};
}

}  // namespace eomgen
