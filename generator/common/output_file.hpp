/// @file All-or-nothing output: a file appears complete or not at all.
#pragma once

#include <string>

namespace eomgen {

/// Writes `text` to a temporary file beside `path`, then renames it into place; a device or
/// a pipe at `path` (/dev/null, a FIFO) is written into instead, and stays what it is.
/// Returns an empty string on success, else what went wrong.
std::string write_file_atomically(const std::string& path, const std::string& text);

/// Why `path` cannot take an output file, said before the work that fills it: it is a
/// folder, or its folder does not exist or cannot be written. Empty when it can.
std::string output_file_refusal(const std::string& path);

/// True when `path` names a device or a pipe (/dev/null, /dev/stdout, a FIFO): output goes
/// into it as it comes, since a file renamed over it would replace it.
bool is_device_or_pipe(const std::string& path);

/// Creates `directory` (and its parents) for output, before the work that fills it.
/// Returns an empty string on success, else what went wrong.
std::string make_output_directory(const std::string& directory);

}  // namespace eomgen
