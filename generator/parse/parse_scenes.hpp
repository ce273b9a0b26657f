/// @file The [scenes.NAME] and [variants.NAME] sections of a model file: the questions
/// asked of the model and the simpler models the user declares (Hiller §1.1).
#pragma once

#include "parse/model_file.hpp"
#include "parse/toml_reader.hpp"

namespace eomgen {

void read_scenes(toml_reader::Reader& r, const toml::node& node, ModelFile& m);
void read_variants(toml_reader::Reader& r, const toml::node& node, ModelFile& m);

}  // namespace eomgen
