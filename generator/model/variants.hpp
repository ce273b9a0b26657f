/// @file Simpler models made from a model (Hiller §1.1: model no more than the question
/// needs): a variant's parameters neglected or replaced, coordinates frozen, small-angle
/// approximations; and a scene's inputs written into the model as functions of time.
/// Each is an ordinary Model that derives, emits and simulates like the original.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"

namespace eomgen {

/// The model named `<name>_<variant>` with the variant applied; frozen coordinates are held
/// at their initial values. Throws std::invalid_argument when an expression breaks (1/m2 with
/// m2 neglected).
Model apply_variant(const Model& model, const Variant& variant);

/// The model with the coordinates `frozen` held at the given values (q = value, der(q) = 0).
Model freeze_coordinates(const Model& model, const std::vector<std::size_t>& frozen, const std::vector<double>& values);

/// The model with each coordinate j of `ties` written as g(q) of the others (a rigid link:
/// q_j = g, der(q_j) = dg/dt) and removed.
Model tie_coordinates(const Model& model, const std::vector<std::pair<std::size_t, GiNaC::ex>>& ties);

/// The scene's inputs replaced by their functions of t, its `set` as the parameter defaults
/// and its `initial` as the initial state; the model keeps its name.
Model apply_scene(const Model& model, const Scene& scene);

/// Every expression of the model with the substitution applied.
void substitute_everywhere(Model& model, const GiNaC::exmap& substitution);

}  // namespace eomgen
