/// @file `eomgen generate --split`: the header's largest functions compiled once each, for double, in
/// translation units of their own, so that a build compiles them in parallel and the files that use
/// the model only parse them (explicit instantiation definitions in the units, `extern template`
/// declarations in NAME_split.hpp). NAME.hpp itself stays as it is, self-contained.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace eomgen {

struct GeneratedFile {
  std::string name;  // file name, without folder
  std::string text;
};

/// A public function template of a generated header (outside its detail namespace).
struct HeaderFunction {
  std::string name, signature;  // signature as in the header, without the body
  std::size_t body_bytes = 0;
};

/// The header's public function templates, in the order the header defines them.
std::vector<HeaderFunction> header_functions(const std::string& header);

/// NAME_split.hpp and one NAME_<function>.cpp for each public function whose body has at least
/// `min_body_bytes` characters; no files when none has. `header_name` is NAME.hpp as the units
/// include it, `model_name` NAME.
std::vector<GeneratedFile> split_units(const std::string& header, const std::string& model_name,
                                       const std::string& header_name, std::size_t min_body_bytes);

}  // namespace eomgen
