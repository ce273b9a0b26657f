/// @file What the numeric commands share: derive a model file, compile its
/// header (cached), load it, and apply --set assignments.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compile/compile_cache.hpp"
#include "pipeline.hpp"
#include "simulation.hpp"

namespace eomgen::studies {

struct Assignment {
  std::string name;
  double value;
};

/// "name=value", one per flag, the value a number; reports mistakes on stderr.
bool parse_assignments(const std::vector<std::string>& texts, const char* flag, std::vector<Assignment>& out);

struct LoadedProblem {
  Equations equations;
  std::unique_ptr<runtime::LoadedModel> compiled;
  runtime::Problem problem;  // parameters and inputs with --set applied
  std::vector<double> initial_state;  // the model's initial values, evaluated with the --set parameters
  std::string header;        // the generated header text
};

/// Derives, compiles and loads; applies --set to parameters or inputs. Returns the
/// exit status on failure (2 for the user's mistakes, 1 for internal errors).
/// The index in the state of a coordinate, a velocity of the state, or der(q) where a
/// pseudo-velocity is defined as der(q); −1 when there is none.
int state_index(const eomgen_model_abi& m, const std::string& name);

/// Applies NAME=VALUE flags (--initial, --at) to the state x; prints the mistake and
/// returns false when a name is not part of the state.
/// `assigned`, when given, marks the entries of x that were named.
bool assign_states(const eomgen_model_abi& m, const std::vector<std::string>& texts, const char* flag, std::vector<double>& x,
                   std::vector<bool>* assigned = nullptr);

/// `reduce`: cyclic coordinates to eliminate by Routh's reduction (their momenta become parameters).
/// `choice`: a scene or variant of the file (pipeline.hpp).
std::optional<int> load_problem(const std::string& model, const std::vector<std::string>& sets, LoadedProblem& out,
                                const std::vector<std::string>& reduce = {}, const ModelChoice& choice = {});

/// The second half of load_problem: generates, compiles and loads derived equations, applies --set.
std::optional<int> load_equations(const Equations& equations, const std::vector<std::string>& sets, LoadedProblem& out);

/// Index of `name` in a C name table, or −1.
int index_of(const char* const* names, std::size_t count, const std::string& name);

}  // namespace eomgen::studies
