// `eomgen generate --split`: the header's public functions found in order with their sizes, units and
// extern declarations written for those over the threshold only, and a program built from the units
// that computes what the whole header computes without compiling the split functions itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "emit/split_units.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

std::string baseline_header(const std::string& name) {
  return read_file(std::string(EOMGEN_SOURCE_DIR) + "/generated/" + name + ".hpp");
}

TEST(SplitUnits, FindsThePublicFunctionsInTheirOrderWithoutTheDetailOnes) {
  std::string header = baseline_header("double_pendulum");
  std::vector<HeaderFunction> found = header_functions(header);
  std::vector<std::string> names;
  for (const HeaderFunction& f : found) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"mass_matrix", "forcing", "rhs", "jacobian_state", "jacobian_input", "linearization",
                                             "kinetic_energy", "potential_energy", "outputs", "first_integrals",
                                             "constraint_jacobian", "constraint_residuals", "rhs_stabilized",
                                             "jacobian_state_stabilized", "multipliers", "body_poses", "drawn_shapes",
                                             "gravity"}));
  const std::string signature = "void rhs(T t, const T* x, const detail::input_t<T>* u, const T* p, T* xdot)";
  EXPECT_EQ(found[2].signature, signature);
  std::size_t body = header.find(signature + " {\n") + signature.size() + 3;
  EXPECT_EQ(found[2].body_bytes, header.find("\n}\n", body) + 1 - body);
}

TEST(SplitUnits, WritesUnitsForTheFunctionsOverTheThresholdOnly) {
  std::string header = baseline_header("double_pendulum");
  std::vector<HeaderFunction> found = header_functions(header);
  std::size_t threshold = found[2].body_bytes;  // rhs's
  std::vector<std::string> expected{"double_pendulum_split.hpp"};
  for (const HeaderFunction& f : found)
    if (f.body_bytes >= threshold) expected.push_back("double_pendulum_" + f.name + ".cpp");
  ASSERT_GE(expected.size(), 2u);
  ASSERT_LT(expected.size(), found.size() + 1);
  std::vector<GeneratedFile> files = split_units(header, "double_pendulum", "double_pendulum.hpp", threshold);
  std::vector<std::string> names;
  for (const GeneratedFile& f : files) names.push_back(f.name);
  EXPECT_EQ(names, expected);
  const std::string instance =
      "void rhs<double>(double t, const double* x, const detail::input_t<double>* u, const double* p, double* xdot);";
  EXPECT_NE(files[0].text.find("#include \"double_pendulum.hpp\""), std::string::npos);
  EXPECT_NE(files[0].text.find("extern template " + instance), std::string::npos) << files[0].text;
  auto rhs_unit = std::find_if(files.begin(), files.end(), [](const GeneratedFile& f) { return f.name == "double_pendulum_rhs.cpp"; });
  ASSERT_NE(rhs_unit, files.end());
  EXPECT_NE(rhs_unit->text.find("\ntemplate " + instance), std::string::npos) << rhs_unit->text;
  EXPECT_TRUE(split_units(header, "double_pendulum", "double_pendulum.hpp", 1u << 30).empty());
}

// rhs and jacobian_state of the default state, printed to 17 digits, from NAME_split.hpp or NAME.hpp
std::string program(const std::string& include) {
  return "#include <cstdio>\n#include \"" + include +
         "\"\n"
         "namespace m = eomgen::models::double_pendulum;\n"
         "int main() {\n"
         "  double xdot[m::num_states], J[m::num_states * m::num_states];\n"
         "  const double* x = m::default_state.data();\n"
         "  m::rhs(0.0, x, m::default_inputs.data(), m::default_parameters.data(), xdot);\n"
         "  m::jacobian_state(0.0, x, m::default_inputs.data(), m::default_parameters.data(), J);\n"
         "  for (double v : xdot) std::printf(\"%.17g\\n\", v);\n"
         "  for (double v : J) std::printf(\"%.17g\\n\", v);\n"
         "}\n";
}

TEST(SplitUnits, AProgramBuiltFromTheUnitsComputesWhatTheHeaderComputes) {
  std::string dir = temporary_directory();
  CommandOutput r = run_eomgen("generate '" + model_path("double_pendulum") + "' -o '" + dir + "' --split --split-above 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("include double_pendulum_split.hpp and compile"), std::string::npos) << r.err;
  for (const char* unit : {"double_pendulum_rhs.cpp", "double_pendulum_jacobian_state.cpp"})
    ASSERT_FALSE(read_file(dir + "/" + unit).empty()) << unit;
  std::ofstream(dir + "/split.cpp") << program("double_pendulum_split.hpp");
  std::ofstream(dir + "/whole.cpp") << program("double_pendulum.hpp");
  const std::string compile = "c++ -std=c++17 -O1 -Wall -Wextra -Wpedantic -Werror -c";
  std::string build = "cd '" + dir + "' && for f in double_pendulum_*.cpp split.cpp; do " + compile +
                      " \"$f\" -o \"${f%.cpp}.o\" || exit 1; done && c++ *.o -o split && ./split > split.txt";
  ASSERT_EQ(run_command(build), 0);
  // the program's own file only declares the split functions: undefined there, defined in the units
  EXPECT_EQ(run_command("cd '" + dir + "' && nm -C split.o | grep -q ' U .*jacobian_state<double>'"), 0);
  ASSERT_EQ(run_command("cd '" + dir + "' && c++ -std=c++17 -O1 whole.cpp -o whole && ./whole > whole.txt"), 0);
  EXPECT_EQ(read_file(dir + "/split.txt"), read_file(dir + "/whole.txt"));
  EXPECT_FALSE(read_file(dir + "/whole.txt").empty());
}

// the units and their extern declarations of Appell's, Hamilton's, Lagrange I's and the articulated
// header's functions (other signatures and function sets) in one file: each explicit instantiation
// matches a function of the header, under -Werror
class SplitModel : public ::testing::TestWithParam<std::string> {};

TEST_P(SplitModel, UnitsAndDeclarationsCompile) {
  std::string dir = temporary_directory(), name = GetParam();
  CommandOutput r = run_eomgen("generate '" + model_path(name) + "' -o '" + dir + "' --split --split-above 1");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_FALSE(read_file(dir + "/" + name + "_split.hpp").empty()) << r.err;
  std::string check = "cd '" + dir + "' && { echo '#include \"" + name + "_split.hpp\"'; for u in " + name +
                      "_*.cpp; do echo \"#include \\\"$u\\\"\"; done; } > check.cpp && "
                      "c++ -std=c++17 -fsyntax-only -Wall -Wextra -Wpedantic -Werror check.cpp";
  EXPECT_EQ(run_command(check), 0) << read_file(dir + "/check.cpp");
}

INSTANTIATE_TEST_SUITE_P(Methods, SplitModel,
                         ::testing::Values("rolling_ball", "n_link_pendulum_4_hamilton", "whipple_bicycle", "crane_hook_tree"));

// a unit the new split no longer has would still compile (and cost time) in a build that takes the
// folder's NAME_*.cpp: it goes, and only eomgen's own files go
TEST(SplitUnits, ASplitRemovesTheUnitsOfTheOneBeforeItAndNothingElse) {
  std::string dir = temporary_directory(), model = model_path("double_pendulum");
  ASSERT_EQ(run_eomgen("generate '" + model + "' -o '" + dir + "' --split --split-above 1").status, 0);
  ASSERT_FALSE(read_file(dir + "/double_pendulum_rhs.cpp").empty());
  std::ofstream(dir + "/double_pendulum_main.cpp") << "// the user's own file\nint main() { return 0; }\n";
  CommandOutput none = run_eomgen("generate '" + model + "' -o '" + dir + "' --split --split-above 100000");
  EXPECT_EQ(none.status, 0) << none.err;
  EXPECT_NE(none.err.find("nothing to split"), std::string::npos) << none.err;
  for (const char* gone : {"double_pendulum_split.hpp", "double_pendulum_rhs.cpp", "double_pendulum_jacobian_state.cpp"})
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + gone)) << gone;
  EXPECT_TRUE(std::filesystem::exists(dir + "/double_pendulum_main.cpp"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/double_pendulum.hpp"));
}

TEST(SplitUnits, SaysWhenNothingIsLargeEnoughAndNeedsSplitForItsThreshold) {
  std::string dir = temporary_directory();
  CommandOutput r = run_eomgen("generate '" + model_path("pendulum") + "' -o '" + dir + "' --split");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("nothing to split"), std::string::npos) << r.err;
  EXPECT_TRUE(read_file(dir + "/pendulum_split.hpp").empty());
  CommandOutput alone = run_eomgen("generate '" + model_path("pendulum") + "' -o '" + dir + "' --split-above 4");
  EXPECT_NE(alone.status, 0);
  EXPECT_NE(alone.err.find("--split"), std::string::npos) << alone.err;
}

}  // namespace
}  // namespace eomgen::test
