/// @file The `shape` key of particles, rigid bodies and frames: what `eomgen animate` draws.
/// One shape is a table, several an array of tables:
///   shape = { type = "box", size = ["a", "b", "c"], offset = [0, 0, "c/2"] }
///   shape = [{ type = "sphere", size = [0.1] }, { type = "capsule", size = [0.02, "l"], axis = [1, 0, 0] }]
#pragma once

#include "parse/model_file.hpp"
#include "parse/toml_reader.hpp"

namespace eomgen {

/// The entry's `shape`, when it has one (key: the entry's key path).
void read_shapes(toml_reader::Reader& r, const toml::table& entry, const std::string& key, std::vector<ShapeEntry>& out);

/// The shape types and how many sizes each takes.
std::size_t shape_size_count(const std::string& type);

}  // namespace eomgen
