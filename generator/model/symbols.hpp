/// @file The symbols of a model: time, parameters, coordinates with their
/// velocities, and inputs, created in model-file order.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

/// A vector (a point or a vector definition) is used through its components NAME.x, NAME.y,
/// NAME.z, each a definition; a 3×3 matrix definition through its entries NAME.xx, NAME.xy, …,
/// NAME.zz (row, then column), and whole where a matrix goes (an inertia, a rotation).
enum class SymbolKind { parameter, coordinate, input, definition, vector, matrix };

struct SymbolInfo {
  SymbolKind kind;
  std::size_t index;
};

struct Symbols {
  GiNaC::realsymbol time{"t"};
  std::vector<std::string> parameter_names;
  std::vector<GiNaC::realsymbol> parameters;
  std::vector<double> parameter_defaults;
  std::vector<std::string> coordinate_names;
  std::vector<GiNaC::realsymbol> coordinates;  // q
  std::vector<GiNaC::realsymbol> velocities;   // der(q), printed as such
  std::vector<double> initial_coordinates, initial_velocities;
  /// The initial values as written, in the parameters: evaluated again when a parameter is overridden.
  std::vector<GiNaC::ex> initial_coordinate_expressions, initial_rate_expressions;
  std::vector<std::string> input_names;
  std::vector<GiNaC::realsymbol> inputs;
  std::vector<double> input_defaults;
  /// [definitions]: names for expressions, written into every expression that uses them
  std::vector<std::string> definition_names;
  std::vector<GiNaC::ex> definitions;
  std::vector<std::string> vector_names;  // vectors and points; their components are definitions
  std::vector<std::string> matrix_names;  // 3×3 matrix definitions; their entries are definitions
  std::map<std::string, SymbolInfo> by_name;

  std::size_t num_coordinates() const { return coordinates.size(); }
  /// Whether `e` contains coordinate j or its rate.
  bool involves(const GiNaC::ex& e, std::size_t j) const { return e.has(coordinates[j]) || e.has(velocities[j]); }
  /// Every name that may appear in an expression, for hints.
  std::vector<std::string> all_names() const;
  /// parameter symbol -> default value
  GiNaC::exmap default_parameter_values() const;
  /// Coordinate i gone from every list (a frozen or dropped coordinate of a simpler model).
  void remove_coordinate(std::size_t i);
};

/// Names a model may not use for its own symbols: time, der, Pi and the functions.
bool is_reserved_name(const std::string& name);
/// [A-Za-z_][A-Za-z0-9_]*
bool is_identifier(const std::string& name);
/// An identifier that is also not a C++ keyword.
bool is_cpp_identifier(const std::string& name);

}  // namespace eomgen
