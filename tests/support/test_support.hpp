/// @file Helpers shared by the tests: deriving the models in models/, writing
/// closed forms over a model's symbols, and comparing at random points.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>
#include <gtest/gtest.h>

#include "derive/equations.hpp"
#include "pipeline.hpp"
#include "parse/json_reader.hpp"

namespace eomgen::test {

/// The source tree's models/NAME.toml.
std::string model_path(const std::string& name);

/// Derives models/NAME.toml; fails the test on any diagnostic.
Equations derive_model(const std::string& name);
/// Derives a model file's text (`path` names it in diagnostics) as `choice` asks (model_written_out(),
/// solved_by()); fails the test on any diagnostic.
Equations derive_text(const std::string& text, const std::string& path = "model.toml", const ModelChoice& choice = {});
/// The file's own model, its rhs solving for q'' in `form`.
ModelChoice solved_by(ForwardDynamics form);
/// The model's parameter called `name`.
GiNaC::ex parameter_named(const Symbols& s, const std::string& name);

/// Parses a closed form with GiNaC's own parser; the symbols are the model's,
/// with the velocity of q written d_q (so the parser is independent of ours).
GiNaC::ex closed_form(const Equations& e, const std::string& text);

/// Random values for every symbol of the model (parameters in [0.5, 2],
/// coordinates in [-3, 3], velocities in [-2, 2], inputs in [-1, 1], t in [0, 2]).
std::vector<GiNaC::exmap> random_points(const Symbols& s, int count, unsigned seed = 12345);

/// x with A x = b, by Gaussian elimination with partial pivoting (A small and regular).
std::vector<double> solved_linear_system(std::vector<std::vector<double>> A, std::vector<double> b);

/// The value of e at a point, as a double; fails the test if it is not a real number.
double value_at(const GiNaC::ex& e, const GiNaC::exmap& point);

/// The point of `e`'s symbols with values given by name (parameters, coordinates, "der(q)", "t"
/// when given, else 0, and "ddq<k>" for the acceleration symbols when given), its intermediates
/// (those of recursive kinematics, then those of the inverse dynamics) evaluated in order: for
/// comparing two derivations of one model, whose symbols are different objects.
GiNaC::exmap point_by_name(const Equations& e, const std::map<std::string, double>& values);

/// |a − b| ≤ tolerance · max(1, |a|, |b|) at every point.
::testing::AssertionResult agree_at_points(const GiNaC::ex& actual, const GiNaC::ex& expected,
                                           const std::vector<GiNaC::exmap>& points, double tolerance = 1e-12);

/// Runs a shell command; returns its exit status (or −1 when it did not exit normally).
int run_command(const std::string& command);

/// Reads a whole file; empty when it does not exist.
std::string read_file(const std::string& path);

/// A fresh temporary directory, removed when the test process ends unless a test failed or
/// EOMGEN_KEEP_TEST_FILES is set.
std::string temporary_directory();


/// Writes `text` as the file FILE_NAME (a robot's `arm.urdf`) into a fresh temporary directory; its path.
std::string write_file(const std::string& file_name, const std::string& text);

/// The model text `eomgen import` writes for the robot file `text`, written as FILE_NAME (an
/// MJCF's `arm.xml`) by write_file; nothing, and why in `diagnostics`, where it is refused.
std::optional<std::string> imported_robot(const std::string& file_name, const std::string& text, Diagnostics& diagnostics);

/// The same for a robot file that must import: its model file, or a test failure naming why and "".
std::string imported_robot_text(const std::string& file_name, const std::string& text);

/// Whether `text` (an imported model file, a message) holds `part`.
inline bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// `text` without its lines that start with `start` ("# note: "): two files' imports compared but for
/// what each says of itself.
std::string without_lines_starting(std::string text, const std::string& start);

/// How many line breaks the text has (an edit that keeps every line where it was keeps this).
long line_breaks(const std::string& text);

/// `text` with each `from` replaced by its `to` (the first occurrence); a `from` it lacks fails the
/// test that asks, naming it (a model file's numbers rescaled for a test).
std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits);

/// Writes `text` as the model file NAME.toml into a fresh temporary directory; its path.
std::string write_model(const std::string& name, const std::string& text);

struct CommandOutput {
  int status;
  std::string out, err;
};
/// Runs the eomgen executable with these arguments and the tests' shared compile cache.
CommandOutput run_eomgen(const std::string& arguments);

/// Whether eomgen was built with MPI and mpirun is there: else the tests of distributed
/// runs are skipped, saying why.
bool can_run_on_ranks();

/// eomgen under `mpirun -np RANKS` (as root and oversubscribed where needed), with the
/// tests' shared compile cache.
CommandOutput run_eomgen_on_ranks(int ranks, const std::string& arguments);

/// `eomgen ARGUMENTS --format json`, expected to succeed, parsed.
JsonValue run_json(const std::string& arguments);

/// The number under `key` in a JSON object, NaN when missing.
double at(const JsonValue& v, const std::string& key);

/// The member `key` of a JSON object, or a null value when missing.
const JsonValue& field(const JsonValue& v, const std::string& key);

/// The numbers of a CSV file, row by row after its header line (returned in `header`).
std::vector<std::vector<double>> read_numeric_csv(const std::string& path, std::string* header = nullptr);

}  // namespace eomgen::test
