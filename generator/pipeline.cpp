#include "pipeline.hpp"

#include <stdexcept>

#include "derive/methods.hpp"
#include "kinematics/mechanics.hpp"
#include "parse/model_file.hpp"

namespace eomgen {

namespace {
Derivation derive(const ModelFile& file, Diagnostics diagnostics) {
  Derivation result;
  if (diagnostics.empty()) {
    Model model = build_model(file, diagnostics);
    if (diagnostics.empty()) {
      if (std::string refusal = method_refusal(model); !refusal.empty()) {
        diagnostics.error({file.path, file.method_where.line, file.method_where.column}, "model.method", refusal);
      } else {
        Mechanics mechanics = compute_mechanics(model);
        try {
          result.equations = (*find_method(model.method))(model, mechanics);
        } catch (const std::invalid_argument& why) {
          diagnostics.error({file.path, file.method_where.line, file.method_where.column}, "model.method", why.what(),
                            "remove a dependent constraint, or choose pseudo-velocities that, with the constraints, "
                            "determine every velocity");
        }
      }
    }
  }
  result.diagnostics = std::move(diagnostics);
  return result;
}
}  // namespace

Derivation derive_model_file(const std::string& path) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_file(path, diagnostics);
  return derive(file, std::move(diagnostics));
}

Derivation derive_model_text(const std::string& text, const std::string& path) {
  Diagnostics diagnostics;
  ModelFile file = parse_model_text(text, path, diagnostics);
  return derive(file, std::move(diagnostics));
}

}  // namespace eomgen
