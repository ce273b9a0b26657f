/// @file The pipeline, one line per stage: parse → model → kinematics → derive.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "derive/equations.hpp"

namespace eomgen {

struct Derivation {
  std::optional<Equations> equations;  // present exactly when diagnostics is empty
  Diagnostics diagnostics;
};

/// Reads a model file and derives its equations of motion by the method it names.
Derivation derive_model_file(const std::string& path);

/// Reads a model file and derives Routh's reduced equations with the coordinates `cyclic`
/// eliminated, their momenta p_<coordinate> as parameters (Hiller §3.8.4).
Derivation derive_reduced_model_file(const std::string& path, const std::vector<std::string>& cyclic);

/// Reads a model file and derives it by `method` instead of the method it names.
Derivation derive_model_file_as(const std::string& path, const std::string& method);

/// Which model of a file to derive: a declared variant, with a scene's inputs, parameters and
/// initial state written in (DESIGN.md [scenes], [variants]); empty names mean none.
struct ModelChoice {
  std::string scene, variant;
  std::vector<std::string> freeze;  // coordinates held at their (the scene's) initial values
  /// every position and rotation multiplied out in q, though the frames carry or read as joints
  /// (but for ball and free joints; build_model: the symbolic analyses, and diff for small trees,
  /// take equations in q)
  bool written_out = false;
  /// how the header's rhs solves for q'': eomgen's choice, or one form to compare with the other
  ForwardDynamics forward_dynamics = ForwardDynamics::chosen;
};

/// The file's own model, written out in q when `written_out`: for the analyses that differentiate
/// or solve the equations symbolically (ModelChoice::written_out).
inline ModelChoice model_written_out(bool written_out = true) {
  ModelChoice choice;
  choice.written_out = written_out;
  return choice;
}

/// Reads a model file and derives the model `choice` names.
Derivation derive_model_file_for(const std::string& path, const ModelChoice& choice);

/// Same, from a file already read (`file.path` names it).
Derivation derive_model_file_for(const ModelFile& file, const ModelChoice& choice);

/// Derives a model already built (and possibly changed: a variant, a scene); `method_where`
/// locates a refusal of its method.
std::optional<Equations> derive_built_model(const Model& model, SourceLocation method_where, Diagnostics& diagnostics);

/// Same, from model text in memory; `path` names it in diagnostics.
Derivation derive_model_text(const std::string& text, const std::string& path, const ModelChoice& choice = {});

}  // namespace eomgen
