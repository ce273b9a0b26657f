#include <gtest/gtest.h>

#include "support/test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>

#include <sys/wait.h>
#include <unistd.h>

#include "import/model_writer.hpp"
#include "pipeline.hpp"

namespace eomgen::test {

std::string model_path(const std::string& name) { return std::string(EOMGEN_SOURCE_DIR) + "/models/" + name + ".toml"; }

Equations derive_model(const std::string& name) {
  Derivation d = derive_model_file(model_path(name));
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format();
  if (!d.equations) throw std::runtime_error("model " + name + " did not derive");
  return *d.equations;
}

ModelChoice solved_by(ForwardDynamics form) {
  ModelChoice choice;
  choice.forward_dynamics = form;
  return choice;
}

Equations derive_text(const std::string& text, const std::string& path, const ModelChoice& choice) {
  Derivation d = derive_model_text(text, path, choice);
  EXPECT_TRUE(d.diagnostics.empty()) << d.diagnostics.format() << "\n" << text;
  if (!d.equations) throw std::runtime_error(path + " did not derive");
  return *d.equations;
}

GiNaC::ex parameter_named(const Symbols& s, const std::string& name) {
  for (std::size_t i = 0; i < s.parameters.size(); ++i)
    if (s.parameter_names[i] == name) return s.parameters[i];
  throw std::runtime_error("no parameter " + name);
}

GiNaC::ex closed_form(const Equations& e, const std::string& text) {
  const Symbols& s = e.symbols;
  GiNaC::symtab table;
  table["t"] = s.time;
  for (std::size_t i = 0; i < s.parameters.size(); ++i) table[s.parameter_names[i]] = s.parameters[i];
  for (std::size_t i = 0; i < s.coordinates.size(); ++i) table[s.coordinate_names[i]] = s.coordinates[i];
  // der(q) is written d_q; Appell's pseudo-velocities by their own names
  for (const auto& v : s.velocities) {
    std::string name = v.get_name();
    table[name.rfind("der(", 0) == 0 ? "d_" + name.substr(4, name.size() - 5) : name] = v;
  }
  for (std::size_t i = 0; i < s.inputs.size(); ++i) table[s.input_names[i]] = s.inputs[i];
  GiNaC::parser reader(table, true);
  return reader(text);
}

std::vector<GiNaC::exmap> random_points(const Symbols& s, int count, unsigned seed) {
  std::mt19937 generator(seed);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(generator); };
  std::vector<GiNaC::exmap> points;
  for (int k = 0; k < count; ++k) {
    GiNaC::exmap p;
    for (const auto& x : s.parameters) p[x] = uniform(0.5, 2.0);
    for (const auto& x : s.coordinates) p[x] = uniform(-3.0, 3.0);
    for (const auto& x : s.velocities) p[x] = uniform(-2.0, 2.0);
    for (const auto& x : s.inputs) p[x] = uniform(-1.0, 1.0);
    p[s.time] = uniform(0.0, 2.0);
    points.push_back(p);
  }
  return points;
}

std::vector<double> solved_linear_system(std::vector<std::vector<double>> A, std::vector<double> b) {
  std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(A[r][c]) > std::abs(A[pivot][c])) pivot = r;
    std::swap(A[c], A[pivot]), std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      double factor = A[r][c] / A[c][c];
      for (std::size_t k = c; k < n; ++k) A[r][k] -= factor * A[c][k];
      b[r] -= factor * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double sum = b[r];
    for (std::size_t k = r + 1; k < n; ++k) sum -= A[r][k] * x[k];
    x[r] = sum / A[r][r];
  }
  return x;
}

double value_at(const GiNaC::ex& e, const GiNaC::exmap& point) {
  GiNaC::ex v = e.subs(point).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
    ADD_FAILURE() << "not a real number: " << v;
    return NAN;
  }
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

GiNaC::exmap point_by_name(const Equations& e, const std::map<std::string, double>& values) {
  const Symbols& s = e.symbols;
  GiNaC::exmap at;
  auto time = values.find("t");
  at[s.time] = time == values.end() ? 0.0 : time->second;
  for (std::size_t i = 0; i < s.parameters.size(); ++i) at[s.parameters[i]] = values.at(s.parameter_names[i]);
  for (std::size_t i = 0; i < s.coordinates.size(); ++i) at[s.coordinates[i]] = values.at(s.coordinate_names[i]);
  // the velocities of the state by their names: der(q), or the pseudo-velocities' own
  for (const GiNaC::realsymbol& v : s.velocities) at[v] = values.at(v.get_name());
  const std::vector<GiNaC::symbol>& ddq = e.acceleration_symbols();
  for (std::size_t i = 0; i < ddq.size(); ++i)
    if (auto a = values.find("ddq" + std::to_string(i)); a != values.end()) at[ddq[i]] = a->second;
  for (const Intermediate& i : e.intermediates) at[i.symbol] = value_at(i.definition, at);
  if (ddq.empty() || !at.count(ddq[0]) || !e.newton_euler()) return at;
  for (const Intermediate& i : e.newton_euler()->acceleration_intermediates) at[i.symbol] = value_at(i.definition, at);
  return at;
}

::testing::AssertionResult agree_at_points(const GiNaC::ex& actual, const GiNaC::ex& expected,
                                           const std::vector<GiNaC::exmap>& points, double tolerance) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    double a = value_at(actual, points[k]), b = value_at(expected, points[k]);
    double scale = std::max({1.0, std::abs(a), std::abs(b)});
    if (!(std::abs(a - b) <= tolerance * scale))
      return ::testing::AssertionFailure() << "at point " << k << ": " << a << " vs " << b << "\n  actual:   "
                                           << actual << "\n  expected: " << expected;
  }
  return ::testing::AssertionSuccess();
}

int run_command(const std::string& command) {
  int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

namespace {

// The test process's scratch directories, removed when it ends unless a test failed (their files are
// then what the failure message names) or EOMGEN_KEEP_TEST_FILES is set.
class ScratchDirectories {
 public:
  ~ScratchDirectories() {
    const testing::UnitTest* tests = testing::UnitTest::GetInstance();
    if (std::getenv("EOMGEN_KEEP_TEST_FILES") || (tests && tests->Failed())) return;
    std::error_code ignored;
    for (const std::string& d : made_) std::filesystem::remove_all(d, ignored);
  }
  std::string make() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string pattern = ::testing::TempDir() + "eomgen_XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!mkdtemp(buffer.data())) throw std::runtime_error("mkdtemp failed");
    made_.push_back(buffer.data());
    return made_.back();
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> made_;
};

}  // namespace

std::string temporary_directory() {
  static ScratchDirectories directories;
  return directories.make();
}

std::string write_file(const std::string& file_name, const std::string& text) {
  std::string path = temporary_directory() + "/" + file_name;
  std::ofstream(path) << text;
  return path;
}

std::optional<std::string> imported_robot(const std::string& file_name, const std::string& text, Diagnostics& diagnostics) {
  return imported_model_text(write_file(file_name, text), diagnostics, false);
}

std::string imported_robot_text(const std::string& file_name, const std::string& text) {
  Diagnostics diagnostics;
  std::optional<std::string> model = imported_robot(file_name, text, diagnostics);
  if (!model) ADD_FAILURE() << file_name << " did not import:\n" << diagnostics.format();
  return model.value_or("");
}

std::string without_lines_starting(std::string text, const std::string& start) {
  for (std::size_t at = text.find(start); at != std::string::npos; at = text.find(start, at))
    if (at == 0 || text[at - 1] == '\n')
      text.erase(at, text.find('\n', at) == std::string::npos ? std::string::npos : text.find('\n', at) + 1 - at);
    else
      ++at;
  return text;
}

long line_breaks(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

std::string write_model(const std::string& name, const std::string& text) { return write_file(name + ".toml", text); }

std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "the text has no \"" << from << "\"";
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

CommandOutput run_eomgen(const std::string& arguments) {
  std::string scratch = temporary_directory();
  int status = run_command("EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                           std::string(EOMGEN_EXECUTABLE) + "' " + arguments + " > '" + scratch + "/out' 2> '" +
                           scratch + "/err'");
  return {status, read_file(scratch + "/out"), read_file(scratch + "/err")};
}

bool can_run_on_ranks() { return std::string(EOMGEN_MPIEXEC).size() > 0; }

CommandOutput run_eomgen_on_ranks(int ranks, const std::string& arguments) {
  std::string scratch = temporary_directory();
  // Open MPI refuses root unless told, and more ranks than cores unless oversubscribed
  std::string flags = std::string(::geteuid() == 0 ? "--allow-run-as-root " : "") + "--oversubscribe";
  int status = run_command("EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                           std::string(EOMGEN_MPIEXEC) + "' " + flags + " -np " + std::to_string(ranks) + " '" +
                           std::string(EOMGEN_EXECUTABLE) + "' " + arguments + " > '" + scratch + "/out' 2> '" + scratch +
                           "/err'");
  return {status, read_file(scratch + "/out"), read_file(scratch + "/err")};
}

std::vector<std::vector<double>> read_numeric_csv(const std::string& path, std::string* header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  if (header) *header = line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

const JsonValue& field(const JsonValue& v, const std::string& key) {
  static const JsonValue missing;
  const JsonValue* found = v.find(key);
  return found ? *found : missing;
}

JsonValue run_json(const std::string& arguments) {
  CommandOutput r = run_eomgen(arguments + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto json = parse_json(r.out, "stdout", d);
  EXPECT_TRUE(json) << d.format() << r.out;
  return json ? *json : JsonValue{};
}

double at(const JsonValue& v, const std::string& key) { return v.find(key) ? v.find(key)->value : NAN; }

}  // namespace eomgen::test
