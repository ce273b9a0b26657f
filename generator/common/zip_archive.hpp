/// @file A zip archive of stored (uncompressed) entries, as an FMU is: local headers, the
/// data, the central directory (PKWARE's APPNOTE, version 2.0 features only). The entries'
/// times are fixed, so the same files give the same bytes.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// (path inside the archive, contents) in the order given.
std::string zip_archive(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace eomgen
