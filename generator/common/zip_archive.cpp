#include "common/zip_archive.hpp"

#include <array>
#include <cstdint>

namespace eomgen {

namespace {

std::uint32_t crc32(const std::string& data) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xffffffffu;
  for (unsigned char b : data) c = table[(c ^ b) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

void put16(std::string& out, std::uint32_t v) { out += char(v & 0xff), out += char((v >> 8) & 0xff); }
void put32(std::string& out, std::uint32_t v) { put16(out, v & 0xffff), put16(out, v >> 16); }

constexpr std::uint32_t dos_time = 0, dos_date = (1 << 5) | 1;  // 1980-01-01 00:00

}  // namespace

std::string zip_archive(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out, directory;
  for (const auto& [path, data] : entries) {
    std::uint32_t offset = std::uint32_t(out.size()), crc = crc32(data), size = std::uint32_t(data.size());
    put32(out, 0x04034b50), put16(out, 10), put16(out, 0), put16(out, 0), put16(out, dos_time), put16(out, dos_date);
    put32(out, crc), put32(out, size), put32(out, size), put16(out, std::uint32_t(path.size())), put16(out, 0);
    out += path;
    out += data;
    put32(directory, 0x02014b50), put16(directory, 0x0314), put16(directory, 10), put16(directory, 0), put16(directory, 0);
    put16(directory, dos_time), put16(directory, dos_date), put32(directory, crc), put32(directory, size), put32(directory, size);
    put16(directory, std::uint32_t(path.size())), put16(directory, 0), put16(directory, 0), put16(directory, 0), put16(directory, 0);
    put32(directory, 0100644u << 16);  // a regular file, rw-r--r--
    put32(directory, offset);
    directory += path;
  }
  std::uint32_t start = std::uint32_t(out.size());
  out += directory;
  put32(out, 0x06054b50), put16(out, 0), put16(out, 0), put16(out, std::uint32_t(entries.size())),
      put16(out, std::uint32_t(entries.size())), put32(out, std::uint32_t(directory.size())), put32(out, start), put16(out, 0);
  return out;
}

}  // namespace eomgen
