/// @file The pipeline, one line per stage: parse → model → kinematics → derive.
#pragma once

#include <optional>
#include <string>

#include "derive/equations.hpp"

namespace eomgen {

struct Derivation {
  std::optional<Equations> equations;  // present exactly when diagnostics is empty
  Diagnostics diagnostics;
};

/// Reads a model file and derives its equations of motion by the method it names.
Derivation derive_model_file(const std::string& path);

/// Same, from model text in memory; `path` names it in diagnostics.
Derivation derive_model_text(const std::string& text, const std::string& path);

}  // namespace eomgen
