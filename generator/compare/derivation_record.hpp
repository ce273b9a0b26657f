/// @file One side of `eomgen diff`: the derived equations of a model file, or of a
/// derived-equations JSON (`eomgen derive --format json`, the files in generated/),
/// as plain named entries in the names of the canonical text: M[i][j], f[i], T, V, R,
/// y[output], g[c], C[c][q], b[c], s[pseudo-velocity], der(q) (kinematic equations), S.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/diagnostic.hpp"

namespace eomgen {

struct DerivedEntry {
  std::string name;  // as in the canonical text
  std::string text;  // the expression, GiNaC syntax with der(q)
};

struct DerivationRecord {
  std::string path, model, method;
  std::vector<std::string> coordinates, velocities, outputs, multipliers;
  std::vector<std::pair<std::string, double>> parameters, inputs;  // with defaults, in file order
  std::vector<DerivedEntry> entries;
  /// a tree's quantities (world poses, twists, composite inertias), in order of computation: the
  /// entries and the later ones use their names
  std::vector<DerivedEntry> intermediates;
  bool pseudo_velocities = false;  // Appell: velocities are pseudo-velocities with kinematic equations
};

/// Reads `path`: a model file (.toml) or a robot file (MJCF, URDF) is derived, written out in q up
/// to 4 velocities and in its tree's quantities beyond (written out, a 7-joint arm took a minute a
/// side); anything else is read as derived-equations JSON. Mistakes (a missing file, a model-file
/// error, a JSON that is not a derivation) go to `diagnostics` with their location.
std::optional<DerivationRecord> read_derivation(const std::string& path, Diagnostics& diagnostics);

}  // namespace eomgen
