/// @file The 3-D structure of a model file: [[frames]], [[points]], the rotations they
/// and the rigid bodies share, and the frame a body is given in.
#pragma once

#include "parse/model_file.hpp"
#include "parse/toml_reader.hpp"

namespace eomgen {

void read_frames(toml_reader::Reader& r, const toml::node& node, ModelFile& m);
void read_points(toml_reader::Reader& r, const toml::node& node, ModelFile& m);

/// `rotation = "rot_z(a)*rot_x(b)"` or a 3×3 array.
std::optional<RotationEntry> read_rotation(toml_reader::Reader& r, const toml::node& node, const std::string& key);

/// `frame = "NAME"` of a body or point, when present: the name and where it was written.
void read_frame_name(toml_reader::Reader& r, const toml::table& t, const std::string& key, std::string& name,
                     SourceLocation& where);

}  // namespace eomgen
